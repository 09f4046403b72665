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

} // namespace

int compareCommand(const CompareRequest& r, std::ostream& out, std::ostream& err) {
    // gxp needs its scale, and the scale and origin mean nothing without gxp (trace.h: the rule
    // the app's --trace-units follows too).
    TraceUnitsSpec units;
    if (const auto refused =
            readTraceUnitsOptions({r.units, r.pxPerM, r.pxOrigin}, "--units", units)) {
        if (refused->text.empty())
            err << "sandbox-cli compare: " << refused->flag << " " << refused->expected << "\n";
        else
            refuse(err, refused->flag.c_str(), refused->text, refused->expected);
        return refused->usage ? kExitUsage : kExitBadInput;
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
    const TraceComparison c =
        compareTrace(scene, reference, trace, traceTolerance(scene, reference.dt, tolerance));
    const ReportContext context{r.scene, &scene, &trace};
    out << (r.json ? reportJson(c, context) : reportText(c, context));
    return c.same() ? kExitOk : kExitDifferent;
}
