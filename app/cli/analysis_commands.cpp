#include "analysis_commands.h"

#include "commands.h"
#include "printable.h"
#include "safe_file.h"
#include "stability.h"
#include "tradeoff.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace {

// Creates the directory; false with a message on `err` when that fails.
bool prepare(const std::string& dir, std::ostream& err) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
        err << printable(dir, kPrintablePath) << ": cannot create the output directory"
            << (ec ? ": " + ec.message() : "") << "\n";
        return false;
    }
    return true;
}

// Writes a file with `write(stream)` through a SafeFile; false with a message on `err` when it
// cannot be written (the file that was there is kept).
template <class Write> bool writeFile(const std::string& path, std::ostream& err, Write&& write) {
    SafeFile file(path);
    write(file.stream());
    std::string error;
    if (!file.commit(&error)) {
        err << error << "\n";
        return false;
    }
    return true;
}

// "wrote PATH" on a line, the path as printable() shows it (a folder's name may hold control
// bytes).
std::string wrote(const std::string& path) {
    return "wrote " + printable(path, kPrintablePath) + "\n";
}

} // namespace

// Both commands run first and create the output directory only then: a run that fails (a scenes
// directory without the scenes) leaves nothing behind.
int tradeoffCommand(const AnalysisRequest& request, std::ostream& out, std::ostream& err) {
    TradeoffOptions options;
    options.scenesDir = request.scenesDir;
    options.quick = request.quick;
    std::vector<TradeoffRow> rows;
    try {
        rows = runTradeoff(options);
    } catch (const std::runtime_error& e) {
        err << printable(e.what(), kPrintablePath) << "\n";
        return kExitBadInput;
    }
    if (!prepare(request.outDir, err)) return kExitBadInput;
    const std::string base = request.outDir + "/tradeoff";
    std::string chartError;
    if (!writeFile(base + ".csv", err, [&](std::ostream& f) { writeTradeoffCsv(f, rows); }) ||
        !writeFile(base + ".md", err, [&](std::ostream& f) { writeTradeoffMarkdown(f, rows); }))
        return kExitBadInput;
    if (!writeTradeoffChart(base + ".png", rows, &chartError)) {
        err << chartError << "\n";
        return kExitBadInput;
    }
    out << rows.size() << " runs\n";
    for (const char* extension : {".csv", ".md", ".png"}) out << wrote(base + extension);
    return kExitOk;
}

int stabilityCommand(const AnalysisRequest& request, std::ostream& out, std::ostream& err) {
    std::vector<StabilityResult> results;
    try {
        results = runStability(request.scenesDir, request.extremesDir);
    } catch (const std::runtime_error& e) {
        err << printable(e.what(), kPrintablePath) << "\n";
        return kExitBadInput;
    }
    if (!prepare(request.outDir, err)) return kExitBadInput;
    const std::string base = request.outDir + "/stability";
    if (!writeFile(base + ".csv", err, [&](std::ostream& f) { writeStabilityCsv(f, results); }) ||
        !writeFile(base + ".md", err, [&](std::ostream& f) { writeStabilityMarkdown(f, results); }))
        return kExitBadInput;
    writeStabilityMarkdown(out, results);
    out << "\n" << wrote(base + ".csv") << wrote(base + ".md");
    return kExitOk;
}
