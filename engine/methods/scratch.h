// The buffers the methods reuse from step to step, so that a step allocates nothing once they have
// grown. A cache only: what a step computes never depends on what they held before. Each World
// owns one (World::scratch), and World::step passes it to the methods in the SubstepContext;
// copying a World gives the copy empty buffers of its own, so two worlds never share them.
#pragma once

#include "broad_phase.h"
#include "collision.h"
#include "corner_grid.h"
#include "crush.h"
#include "resolve.h"

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

// The perfect method's buffers (perfect.cpp).
struct PerfectScratch {
    // A predicted impact.
    struct Event {
        double time;          // s since the substep start
        int a;                // the block that predicted the impact
        int b;                // the other block, or -1 for the bounds
        std::uint32_t stampA; // a's stamp when predicted
        std::uint32_t stampB; // b's stamp when predicted (0 for walls)
        std::uint8_t axes;    // kAxisX | kAxisY
    };
    std::vector<double> clock;        // s: the time at which each block's position is valid
    std::vector<std::uint32_t> stamp; // per block, incremented on every change of velocity
    CrushRule crush;                  // bounces between infinite masses, per block and axis
    std::vector<Event> events;        // predicted impacts, a binary heap once the first are in
    std::vector<int> changed;         // blocks whose velocity an event changed
    std::unordered_map<std::uint64_t, int> metAtInstant; // meetings per pair at one instant
    CornerGrid cornerGrid;                               // the paths, for blocks of similar size

    // Windows (perfect.cpp, "Windows"): for substeps in which blocks cross the world many times.
    // A block's motion: its position and velocity, valid at `clock` (s since the substep start).
    struct Motion {
        Vec2 position;
        Vec2 velocity;
        double clock;
    };
    // How the windows are used: 0 when the substep's motion calls for them (the default), -1
    // never, a positive factor always, with windows that many times shorter than the default
    // (tests compare the three: the impacts found, and so every result, are the same).
    double windowPolicy = 0.0;
    CornerGrid windowGrid; // each block's current window (or, for very mixed sizes, in:)
    BroadPhase windows;
    std::vector<int> horizons;      // every block, a binary heap by windowEnd (earliest first)
    std::vector<int> horizonSlot;   // per block: its place in `horizons`
    std::vector<Event> pendingWall; // per block: its wall impact, until its window reaches it
    std::vector<std::uint32_t> changeSerial;    // per block: the event of its last change (0: none)
    std::vector<double> changeTime;             // s: per block, the time of that change
    std::vector<Aabb> changePath;               // per block: its trajectory from that change
    std::vector<std::vector<Motion>> motions;   // per block: its motion then, and after each sync
    std::vector<double> windowStart, windowEnd; // s: per block, its current window [start, end)
    std::vector<std::uint32_t> windowBatch;     // per block: the batch that registered it
    std::vector<int> windowCount;               // per block: windows since its last change
    std::uint64_t horizonsPassed = 0; // windows after a block's first, all substeps (for tests)
};

// The turn-based method's buffers (turn_based.cpp).
struct TurnBasedScratch {
    // A block's first impact in its turn.
    struct FirstImpact {
        double time = kNever; // s into the block's remaining turn
        std::uint8_t wallAxes = 0;
        // Blocks hit at that same time, each with its axes.
        std::vector<std::pair<int, std::uint8_t>> blocks;
    };
    FirstImpact first;
    CrushRule crush;
    std::vector<std::pair<std::uint64_t, int>> meetings; // per pair, at the current instant
    std::unordered_map<std::uint64_t, int> meetingMap;   // the same past a few listed pairs
    std::vector<std::pair<int, int>> pending;            // (block, axis) whose velocity changed
    std::vector<std::uint8_t> isPending;                 // 2 per block: in `pending` now
    // One change of velocity: enough to undo it.
    struct VelocityChange {
        int block;
        int axis;
        double before; // m/s
    };
    std::vector<VelocityChange> undo; // at the current instant
};

struct StepScratch {
    BroadPhase broadPhase;  // the methods' broad phase (every substep builds it anew)
    BroadPhase overlapGrid; // maxOverlap's own, so measuring never touches the stepping grid
    std::vector<std::pair<int, int>> overlappingPairs; // move-and-correct
    std::vector<Vec2> acceleration; // the exact integrator's, per block (World::step)
    std::vector<Vec2> forces;       // the forces alone, at the substep's start (exact integrator)
    std::vector<Slide> slides;      // friction with the exact integrator: 2 per block
    TurnBasedScratch turnBased;
    PerfectScratch perfect;
};
