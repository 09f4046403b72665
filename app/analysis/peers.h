// The peer engines behind makePeerSimulation, each in its own file and built only when its
// Debian package is installed (libbox2d-dev, libchipmunk-dev).
#pragma once

#include "simulation.h"

std::unique_ptr<Simulation> makeBox2dSimulation(const Scene& scene, double dt, int substeps);
std::unique_ptr<Simulation> makeChipmunkSimulation(const Scene& scene, double dt, int substeps);

// Largest overlap (m) among the blocks and with the walls, pair by pair (peers are measured on
// small scenes only).
double bruteForcePenetration(const std::vector<Block>& blocks, const Bounds& bounds);
