// Methods side by side: the same scene under the lecture's three methods at once, three worlds
// stepped together from one starting state, with running statistics and the divergence from the
// perfect method. Pure logic; side_by_side_overlay.cpp draws the ghosts and the table.
#pragma once

#include "world.h"

#include <array>
#include <cstdint>

struct MethodRun {
    World world;
    StepStats stats;   // the last step's
    StepTotals totals; // since start()
};

struct MethodsSideBySide {
    bool running = false;
    std::array<MethodRun, static_cast<std::size_t>(Method::Count)> runs;

    // Copies `world` once per method (each with its own method).
    void start(const World& world);
    void stop() { running = false; }
    // Steps the three worlds one frame, with `live`'s settings (the sliders) except the method;
    // block `pushed` (when >= 0) feels `thrust` (N) besides its own force this frame. The run of
    // method `followed` (when not Method::Count) is not stepped here: follow() gives it the live
    // world's step (see following()).
    void step(const WorldSettings& live, int pushed = -1, Vec2 thrust = {},
              Method followed = Method::Count);
    // The method whose run is `live`'s state bit for bit (its blocks, bounds, time and frame):
    // live's own method when its run has not parted from it (an edit, a drag, an undo part them),
    // else Method::Count. That run's step, with live's settings and no force of its own added, is
    // the live world's step (World::step is a function of that state and the settings; the
    // methods' buffers hold no result): taken from it rather than computed twice.
    Method following(const World& live) const;
    // After live's step (from the state following() compared, with the same settings): the run
    // of `followed` takes live's new state and `stats` as its own step's.
    void follow(Method followed, const World& live, const StepStats& stats);
    // Largest distance (m) between a block under `method` and the same block under perfect.
    double divergence(Method method) const;
    const MethodRun& run(Method method) const { return runs[static_cast<std::size_t>(method)]; }
};
