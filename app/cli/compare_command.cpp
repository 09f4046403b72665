#include "compare_command.h"

#include "commands.h"
#include "compare.h"
#include "input_limits.h"
#include "printable.h"
#include "report.h"

#include <ostream>

namespace {

bool refuse(std::ostream& err, const char* option, const std::string& value,
            const std::string& expected) {
    err << "sandbox-cli compare: " << option << " " << printable(value) << ": " << expected << "\n";
    return false;
}

// Parses "X,Y" (pixels, each within the coordinates' limits).
bool pixelPair(const std::string& text, Vec2& v, std::ostream& err) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos)
        return refuse(err, "--px-origin", text, "must be X,Y in pixels, e.g. 40,40");
    for (int k = 0; k < 2; ++k) {
        const std::string part = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
        if (std::string p = limits::textViolation(part, limits::kMagnitude, v[k]); !p.empty())
            return refuse(err, "--px-origin", text, p);
    }
    return true;
}

} // namespace

int compareCommand(const CompareRequest& r, std::ostream& out, std::ostream& err) {
    // Usage first: gxp needs its scale, and the scale and origin mean nothing without gxp.
    TraceUnitsSpec units;
    if (r.units && !parseTraceUnits(*r.units, units.units)) {
        refuse(err, "--units", *r.units, "must be si or gxp");
        return kExitUsage;
    }
    const bool gxp = units.units == TraceUnits::Gxp;
    if (gxp && !r.pxPerM) {
        err << "sandbox-cli compare: --units gxp needs --px-per-m N (pixels per metre)\n";
        return kExitUsage;
    }
    if (!gxp && (r.pxPerM || r.pxOrigin)) {
        err << "sandbox-cli compare: --px-per-m and --px-origin are for --units gxp\n";
        return kExitUsage;
    }
    std::optional<Method> method;
    if (r.method) {
        Method m{};
        if (!parseMethod(r.method->c_str(), m)) {
            refuse(err, "--method", *r.method, "must be perfect, move-and-correct or turn-based");
            return kExitBadInput;
        }
        method = m;
    }
    if (gxp) {
        const limits::Range scale{1e-6, 1e9, "px/m"};
        if (std::string p = limits::textViolation(*r.pxPerM, scale, units.pxPerM); !p.empty()) {
            refuse(err, "--px-per-m", *r.pxPerM, p);
            return kExitBadInput;
        }
        if (r.pxOrigin && !pixelPair(*r.pxOrigin, units.originPx, err)) return kExitBadInput;
    }
    double tolerance = 0.0;
    if (r.tolerance) {
        const limits::Range range{1e-12, 1e9, "m"};
        if (std::string p = limits::textViolation(*r.tolerance, range, tolerance); !p.empty()) {
            refuse(err, "--tolerance", *r.tolerance, p);
            return kExitBadInput;
        }
    }

    const SceneResult loaded = loadSceneFile(r.scene);
    if (!loaded.scene) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    const Scene& scene = *loaded.scene;
    const WorldSettings reference = referenceSettings(scene, method);
    const TraceResult read = loadTraceFile(r.trace, scene, reference.dt, units);
    if (!read.trace) {
        err << read.error.text() << "\n";
        return kExitBadInput;
    }
    const Trace& trace = *read.trace;
    const Comparison c =
        compareTrace(scene, reference, trace, traceTolerance(scene, reference.dt, tolerance));
    const ReportContext context{r.scene, &scene, &trace};
    out << (r.json ? reportJson(c, context) : reportText(c, context));
    return c.same() ? kExitOk : kExitDifferent;
}
