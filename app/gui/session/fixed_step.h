// The fixed-timestep accumulator: the simulation advances in ticks of dt whatever the display
// rate. Pure logic; the caller passes the real time that passed.
#pragma once

#include <algorithm>

// The lecture's slow motion: the simulation advances this many frames per real second.
constexpr double kSlowMotionFramesPerSecond = 5.0;

struct FixedStepClock {
    double accumulator = 0.0; // s of simulated time owed to the simulation
    int maxTicksPerFrame = 8; // cap, so a slow frame cannot snowball (spiral of death)

    // Adds `realSeconds * rate` simulated seconds and returns how many ticks of `dt` to run now.
    // When the cap is hit, the time still owed is dropped: the simulation slows down instead of
    // falling ever further behind.
    int advance(double realSeconds, double dt, double rate) {
        if (!(dt > 0.0) || !(realSeconds > 0.0) || !(rate > 0.0)) return 0;
        accumulator += std::min(realSeconds, 0.25) * rate;
        int ticks = 0;
        while (accumulator >= dt && ticks < maxTicksPerFrame) {
            accumulator -= dt;
            ++ticks;
        }
        if (ticks == maxTicksPerFrame && accumulator >= dt) accumulator = 0.0;
        return ticks;
    }

    void reset() { accumulator = 0.0; }
};

// Simulated seconds per real second: the time-scale slider, or slow motion's 5 frames per second.
inline double simulationRate(double timeScale, bool slowMotion, double dt) {
    return slowMotion ? kSlowMotionFramesPerSecond * dt : timeScale;
}
