// A student's trace against one simulation of the scene, frame by frame: the first frame where a
// position or a velocity differs beyond the tolerance, and the largest differences over the run.
// Positions and velocities are judged apart: a block at rest in the reference may report a small
// velocity its position never shows (gravity's g·dt, printed before the floor took it away), and
// that alone is no difference.
#pragma once

#include "trace.h"

#include <cstdint>
#include <string>

// What counts as the same. The default: a thousandth of the smallest block for positions (float
// rounding in a single-precision engine stays near 1e-4 m over a few hundred frames, a real
// difference is a fraction of a block), and for velocities the speed that covers that distance
// in one frame.
struct Tolerance {
    double position = 0.0; // m
    double velocity = 0.0; // m/s
    std::string why;       // how the numbers were chosen, for the report
};

// The default tolerance for `scene` at frame length `dt`; `position` > 0 replaces its position
// tolerance (the velocity one follows: position / dt).
Tolerance traceTolerance(const Scene& scene, double dt, double position = 0.0);

// One number of the trace against the simulation's at one frame.
struct Difference {
    std::int64_t frame = -1; // -1: none
    int block = -1;          // scene index
    int axis = 0;            // 0 = x, 1 = y
    bool velocity = false;   // a velocity component (else a position)
    double yours = 0.0;      // the trace's value (m or m/s)
    double reference = 0.0;  // the simulation's
    int line = 0;            // the trace's line
    bool found() const { return frame >= 0; }
    double by() const; // |yours - reference|
};

struct RunMatch {
    Difference position; // the first position beyond the tolerance
    Difference velocity; // the first velocity beyond it (a resting block's excused)
    Difference resting;  // the first velocity excused: the block rests in the simulation and
                         // its position agrees
    double maxPositionError = 0.0; // m, over every traced frame and block
    double maxVelocityError = 0.0; // m/s, the same (excused ones included)
    std::int64_t lastFrame = 0;    // the last frame compared
    std::uint64_t hash = 0;        // of every simulated state: equal runs have equal hashes
    bool same() const { return !position.found() && !velocity.found(); }
    // The earlier of the two first differences (the position's on a tie).
    const Difference& first() const;
};

// Simulates `scene` under `settings` up to the trace's last frame and compares every traced
// frame.
RunMatch matchRun(const Scene& scene, const WorldSettings& settings, const Trace& trace,
                  const Tolerance& tolerance);
