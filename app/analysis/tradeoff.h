// Speed versus accuracy: every method (and peer) over a sweep of dt and substeps on scenes whose
// answer is known, each run giving a cost (ms of stepping per simulated second) and an error.
// Where gravity makes the integrator matter (the bounce, the stack, the
// block sliding to rest under friction) the methods run with the
// exact integrator too, as engines named "METHOD, exact".
#pragma once

#include <ostream>
#include <string>
#include <vector>

struct TradeoffRow {
    std::string engine; // "perfect", "move-and-correct", "turn-based", or a peer ("box2d")
    std::string scene;  // scene file stem, e.g. "single_bounce"
    double dt = 0.0;    // s per frame
    int substeps = 1;
    double msPerSimulatedSecond = 0.0; // cost
    double error = 0.0;                // the scene's error measure (see errorUnit)
    std::string errorUnit;             // what the error means, e.g. "m" or "relative energy"
    std::string integrator = "semi-implicit-euler"; // the engine's (peers: their own)
    std::vector<std::string> lacks; // a peer's row: the scene's settings it ran without
};

struct TradeoffOptions {
    std::string scenesDir;           // where the scene files are
    bool quick = false;              // fewer dt values (for tests)
    bool peers = true;               // include Box2D and Chipmunk when built with them
    std::vector<std::string> scenes; // only these scenes (file stems); empty: all
};

// Runs the sweep. Throws std::runtime_error naming the file when a scene cannot be loaded.
std::vector<TradeoffRow> runTradeoff(const TradeoffOptions& options);

void writeTradeoffCsv(std::ostream& out, const std::vector<TradeoffRow>& rows);
void writeTradeoffMarkdown(std::ostream& out, const std::vector<TradeoffRow>& rows);
// Error against cost, log-log, one series per engine; one panel per scene. False with a message
// in `error` when the PNG cannot be written.
bool writeTradeoffChart(const std::string& path, const std::vector<TradeoffRow>& rows,
                        std::string* error);
