// A comparison as the student reads it: the plain report of `sandbox-cli compare`, its JSON
// (--json), and the sentences the app shows. The words are the lecture's; every number is one of
// the comparison's, printed as the inspector prints numbers.
#pragma once

#include "compare.h"

#include <string>
#include <vector>

// What the report says about where the scene and the trace came from.
struct ReportContext {
    std::string scenePath;
    const Scene* scene = nullptr;
    const Trace* trace = nullptr;
};

// "mover's y" / "m1 = 1 kg's vx": the quantity of a difference.
std::string differenceName(const Scene& scene, const Difference& d);
// The diagnosis in sentences, best explanation first (the app's inspector shows them).
std::vector<std::string> diagnosisLines(const TraceComparison& c);
// The whole report, lines ending in "\n".
std::string reportText(const TraceComparison& c, const ReportContext& context);
// One JSON object (ASCII only).
std::string reportJson(const TraceComparison& c, const ReportContext& context);
