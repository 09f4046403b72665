// The stability matrix: failure scenes x methods, each with its measured outcome, so a change in
// behaviour either way is noticed (tests assert the known outcomes).
#pragma once

#include <ostream>
#include <string>
#include <vector>

struct StabilityResult {
    std::string scene;     // scene file stem
    std::string method;    // "perfect", "move-and-correct", "turn-based"
    std::string verdict;   // short outcome: "tunnels", "stable", "3141 collisions", ...
    bool fails = false;    // the method shows the scene's failure
    double value = 0.0;    // the measured number behind the verdict
    std::string detail;    // what was measured, with units
    double friction = 0.0; // the world's mu in the run (a scene may run with and without)
};

// The row's name: the scene, and its friction when there is any ("pile (friction 0.5)").
std::string rowName(const StabilityResult& r);

// Runs every failure scene under every method, and the energy extremes (issue 28) from
// `extremesDir` unless it is empty; only the scenes named in `only` (file stems) when it is not
// empty. Throws std::runtime_error naming the file when a scene cannot be loaded.
std::vector<StabilityResult> runStability(const std::string& scenesDir,
                                          const std::string& extremesDir = "",
                                          const std::vector<std::string>& only = {});

void writeStabilityCsv(std::ostream& out, const std::vector<StabilityResult>& results);
void writeStabilityMarkdown(std::ostream& out, const std::vector<StabilityResult>& results);
