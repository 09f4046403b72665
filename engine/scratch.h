// The buffers the methods reuse from step to step, so that a step allocates nothing once they have
// grown. A cache only: what a step computes never depends on what they held before. Each World
// owns one (World::scratch), and World::step passes it to the methods in the SubstepContext;
// copying a World gives the copy empty buffers of its own, so two worlds never share them.
#pragma once

#include "broad_phase.h"
#include "corner_grid.h"

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
    // Per block and axis: the infinite mass it last bounced off (a block index or -1 for a
    // wall), on which side (+1 above), and how many times in a row it alternated between closing
    // ones (the crush rule).
    struct Bounce {
        int anchor = 0;
        int side = 0;
        int alternations = 0;
    };
    std::vector<double> clock;        // s: the time at which each block's position is valid
    std::vector<std::uint32_t> stamp; // per block, incremented on every change of velocity
    std::vector<Bounce> bounces;      // 2 per block
    std::vector<Event> events;        // predicted impacts, a binary heap once the first are in
    std::vector<int> changed;         // blocks whose velocity an event changed
    std::unordered_map<std::uint64_t, int> metAtInstant; // meetings per pair at one instant
    CornerGrid cornerGrid;                               // the paths, for blocks of similar size
};

struct StepScratch {
    BroadPhase broadPhase;  // the methods' broad phase (every substep builds it anew)
    BroadPhase overlapGrid; // maxOverlap's own, so measuring never touches the stepping grid
    std::vector<std::pair<int, int>> overlappingPairs;           // move-and-correct
    std::vector<std::pair<int, std::uint8_t>> firstImpactBlocks; // turn-based: hits at one time
    PerfectScratch perfect;
};
