// The --verbose log: one stdout line per observable state change of the view and the run
// (pause, overlays, thrust, selection, ...), found by comparing snapshots between frames; the
// edits of the world print their own line where they are applied (SimulationSession::apply). It
// lets the end-to-end test check that a key or a slider acted, and lets a lecturer keep a record of
// a session.
#pragma once

#include "lesson_session.h"
#include "overlays.h"
#include "simulation_session.h"
#include "view.h"
#include "world.h"

#include <string>
#include <vector>

struct LoggedState {
    std::string scene;
    bool paused = false;
    bool slowMotion = false;
    Overlays overlays;
    bool uiVisible = true;
    bool thrust = false;
    double thrustX = 0.0, thrustY = 0.0; // N, the held thrust this frame (zero: none)
    std::string playerKeys; // the player's keys the arrows hold ("left+up"; "" none or scripted)
    double timeScale = 0.0;
    float uiScale = 0.0f;
    int selected = -1;
    int trailLength = 0;
    std::string lesson; // "3 / 20 · title", with " (answer)" once revealed
};

// --verbose, and what it compares with.
struct VerboseLog {
    bool verbose = false; // print state changes to stdout
    LoggedState last;     // the state at the last frame logged
    bool lastValid = false;
    bool layoutLogged = false; // the Simulation sliders' places printed once (window test)
};

LoggedState snapshotForLog(const SimulationSession& sim, const View& view,
                           const LessonSession& lesson);
// The lines describing what changed from `before` to `after` ("paused", "method: turn-based").
std::vector<std::string> describeChanges(const LoggedState& before, const LoggedState& after);
