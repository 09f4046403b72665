// sandbox-cli compare: a student's trace against the reference (issue 29; app/compare).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

// `compare`, as typed: option values stay text until compareCommand checks them.
struct CompareRequest {
    std::string scene;                    // scene file
    std::string trace;                    // CSV file
    std::optional<std::string> method;    // the reference's method (default: the scene's)
    std::optional<std::string> units;     // "si" | "gxp"
    std::optional<std::string> pxPerM;    // gxp: pixels per metre
    std::optional<std::string> pxOrigin;  // gxp: "X,Y", the pixel of the world's top-left corner
    std::optional<std::string> tolerance; // m, positions (velocities: that per frame)
    bool json = false;
};

// Exit codes: 0 the same within the tolerance, 3 different (the report says where and why),
// 1 bad input (the scene, the trace or an option's value), 2 bad usage.
inline constexpr int kExitDifferent = 3;

int compareCommand(const CompareRequest& request, std::ostream& out, std::ostream& err);
