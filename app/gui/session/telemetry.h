// What the plots and the inspector read: time series of the watched block's velocity, the total
// momentum and the energies, the times of collisions (the plots' markers), and the last resolved
// collisions with their numbers. Recorded once per simulation frame; pure logic.
#pragma once

#include "plot_logic.h"
#include "velocity_space.h"
#include "world.h"

#include <cstddef>
#include <deque>
#include <vector>

constexpr std::size_t kRecentCollisions = 24;
constexpr std::size_t kCollisionMarkers = 512;

struct Telemetry {
    TimeSeries velocity{2, 3600};             // vx, vy of `watched`
    int watched = -1;                         // block the velocity series belongs to
    TimeSeries momentum{2, 3600};             // px, py
    TimeSeries energy{3, 3600};               // kinetic, potential, total
    std::deque<double> collisionTimes;        // every collision (not the rest rule), newest last
    std::deque<double> watchedCollisionTimes; // those of the watched block
    std::deque<CollisionRecord> recent;       // newest last, at most kRecentCollisions
    VelocitySpacePath velocitySpace;          // the two dynamic blocks' state (velocity_space)

    void clear();
    // What it holds, in bytes: fixed by its sizes (3,600 samples a series, 512 markers, 20,000
    // velocity-space samples), under 2 MB whatever the scene.
    std::size_t bytes() const;
    // Samples `world` (after a step) and appends this frame's `log`. The watched block is
    // `selected`, or the first dynamic block when nothing is selected; a change restarts its
    // series.
    void record(const World& world, int selected, const std::vector<CollisionRecord>& log);
    // The timeline went back to `t`: forget what came after.
    void truncateAfter(double t);
};

// The block whose velocity is plotted: `selected` when valid, else the first dynamic block, else
// -1.
int watchedBlock(const World& world, int selected);
