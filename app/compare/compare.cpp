#include "compare.h"

#include <algorithm>

WorldSettings referenceSettings(const Scene& scene, std::optional<Method> method) {
    WorldSettings s = scene.settings;
    s.mistakes = 0;
    if (method) s.method = *method;
    return s;
}

namespace {

// Runs every variant (the reference first, already matched), keeping one of each set of
// variants that simulate the same bit for bit (the simplest: the list is simplest first).
std::vector<VariantFit> fitVariants(const Scene& scene, const std::vector<Variant>& variants,
                                    const Trace& trace, const Tolerance& tol,
                                    std::vector<VariantFit> fits) {
    for (const Variant& v : variants) {
        RunMatch m = matchRun(scene, v.settings, trace, tol);
        const auto twin = std::find_if(fits.begin(), fits.end(),
                                       [&](const VariantFit& f) { return f.match.hash == m.hash; });
        if (twin != fits.end()) {
            twin->sameAs.push_back(v);
            continue;
        }
        fits.push_back({v, std::move(m), {}});
    }
    return fits;
}

// Better at reproducing the trace: same over more of it, then the smaller position error, then
// the smaller velocity error, then the simpler (fewer changes: the list's order is kept).
bool fitsBetter(const VariantFit& a, const VariantFit& b) {
    const auto reach = [](const RunMatch& m) {
        return m.same() ? m.lastFrame + 1 : m.first().frame;
    };
    if (reach(a.match) != reach(b.match)) return reach(a.match) > reach(b.match);
    if (a.match.maxPositionError != b.match.maxPositionError)
        return a.match.maxPositionError < b.match.maxPositionError;
    return a.match.maxVelocityError < b.match.maxVelocityError;
}

} // namespace

TraceComparison compareTrace(const Scene& scene, const WorldSettings& reference, const Trace& trace,
                             const Tolerance& tolerance) {
    TraceComparison c;
    c.reference = reference;
    c.tolerance = tolerance;
    c.frames = static_cast<std::int64_t>(trace.rows.size());
    if (scene.settings.mistakes)
        c.notes.push_back("the scene turns on a mistake of the Tips slides to show it; the "
                          "reference is the engine without it");
    c.match = matchRun(scene, reference, trace, tolerance);
    if (c.same()) return c;
    c.parting = findPartingCollision(scene, reference, trace, c.match, tolerance);

    std::vector<VariantFit> fits;
    fits.push_back({Variant{reference, {}}, c.match, {}});
    std::vector<Variant> singles = variantsOf(reference, false);
    singles.erase(singles.begin()); // the reference, matched above
    fits = fitVariants(scene, singles, trace, tolerance, std::move(fits));
    auto explains = [](const VariantFit& f) { return f.match.same(); };
    if (std::none_of(fits.begin() + 1, fits.end(), explains)) {
        // Two mistakes at once, only when one change explains nothing.
        std::vector<Variant> pairs = variantsOf(reference, true);
        pairs.erase(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(singles.size() + 1));
        fits = fitVariants(scene, pairs, trace, tolerance, std::move(fits));
    }
    std::stable_sort(fits.begin() + 1, fits.end(), fitsBetter);
    for (auto f = fits.begin() + 1; f != fits.end(); ++f)
        if (explains(*f)) c.explaining.push_back(*f);
    // The closest, when none explains: only one that follows the trace further than the
    // reference does.
    if (c.explaining.empty() && fits.size() > 1 &&
        fits[1].match.first().frame > c.match.first().frame)
        c.closest = fits[1];
    return c;
}
