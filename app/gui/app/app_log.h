// The --verbose log: one stdout line per observable state change (pause, method, sliders, ...),
// found by comparing snapshots between frames. It lets the end-to-end test check that a key or
// a slider acted, and lets a lecturer keep a record of a session.
#pragma once

#include "lesson_session.h"
#include "overlays.h"
#include "simulation_session.h"
#include "view.h"

#include <string>
#include <vector>

struct LoggedState {
    std::string scene;
    bool paused = false;
    bool slowMotion = false;
    Overlays overlays;
    bool uiVisible = true;
    std::string method;
    double bounciness = 0.0;
    double gravityX = 0.0, gravityY = 0.0;
    double dt = 0.0;
    int substeps = 0;
    std::string resolve, integrator;
    unsigned mistakes = 0;
    double drag = 0.0;
    bool thrust = false;
    double thrustX = 0.0, thrustY = 0.0; // N, the held thrust this frame (zero: none)
    double timeScale = 0.0;
    float uiScale = 0.0f;
    int blocks = 0;
    int selected = -1;
    int trailLength = 0;
    std::string lesson; // "3 / 20 · title", with " (answer)" once revealed
};

// --verbose, and what it compares with.
struct VerboseLog {
    bool verbose = false; // print state changes to stdout
    LoggedState last;     // the state at the last frame logged
    bool lastValid = false;
    bool layoutLogged = false; // one slider's place printed once (for the window test)
};

LoggedState snapshotForLog(const SimulationSession& sim, const View& view,
                           const LessonSession& lesson);
// The lines describing what changed from `before` to `after` ("paused", "method: turn-based").
std::vector<std::string> describeChanges(const LoggedState& before, const LoggedState& after);
