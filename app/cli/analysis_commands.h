// `sandbox-cli tradeoff` and `sandbox-cli stability`: the speed-versus-accuracy sweep and the
// stability matrix, written as files into an output directory.
#pragma once

#include <iosfwd>
#include <string>

struct AnalysisRequest {
    std::string outDir;      // created if missing
    std::string scenesDir;   // where the scene files are
    std::string extremesDir; // stability: where the energy extremes are (empty: left out)
    bool quick = false;      // tradeoff: three frame rates instead of nine
};

// Writes tradeoff.csv, tradeoff.md and tradeoff.png. Returns an ExitCode.
int tradeoffCommand(const AnalysisRequest& request, std::ostream& out, std::ostream& err);
// Writes stability.csv and stability.md and prints the matrix. Returns an ExitCode.
int stabilityCommand(const AnalysisRequest& request, std::ostream& out, std::ostream& err);
