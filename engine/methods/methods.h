// The lecture's three simulation methods, one file each. Each advances every block over one
// substep of ctx.h seconds and resolves the collisions it finds. The forces (gravity, a block's
// own, drag) are the integrator's (World::step): semi-implicit Euler has changed the velocities
// already, the exact integrator hands the methods each block's acceleration (ctx.acceleration,
// the paths are parabolas), and explicit Euler changes the velocities after the method.
#pragma once

#include "resolve.h"

// perfect.cpp: repeat { earliest time of impact; move everything to it; resolve } (event-driven).
void advancePerfect(SubstepContext& ctx);
// move_and_correct.cpp: move everything, then push overlapping pairs apart and resolve.
void advanceMoveAndCorrect(SubstepContext& ctx);
// turn_based.cpp: each block in order moves until its first collision, others held still.
void advanceTurnBased(SubstepContext& ctx);
