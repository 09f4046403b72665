#include "compare.h"

#include <algorithm>

WorldSettings referenceSettings(const Scene& scene, std::optional<Method> method) {
    WorldSettings s = scene.settings;
    s.mistakes = 0;
    if (method) s.method = *method;
    return s;
}

namespace {

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
    TraceComparer comparer(scene, reference, trace, tolerance);
    while (!comparer.done()) comparer.step();
    return comparer.take();
}

TraceComparer::TraceComparer(const Scene& scene, const WorldSettings& reference, const Trace& trace,
                             const Tolerance& tolerance)
    : scene_(scene), trace_(trace) {
    c_.reference = reference;
    c_.tolerance = tolerance;
    c_.frames = static_cast<std::int64_t>(trace.rows.size());
    if (scene.settings.mistakes)
        c_.notes.push_back("the scene turns on a mistake of the Tips slides to show it; the "
                           "reference is the engine without it");
    singles_ = variantsOf(reference, false);
    singles_.erase(singles_.begin()); // the reference, matched first
}

int TraceComparer::runsPlanned() const {
    return 1 + static_cast<int>(singles_.size() + pairs_.size());
}

void TraceComparer::step() {
    switch (phase_) {
    case Phase::Reference:
        c_.match = matchRun(scene_, c_.reference, trace_, c_.tolerance);
        ++runs_;
        if (c_.same()) {
            singles_.clear();
            phase_ = Phase::Done;
            return;
        }
        c_.parting = findPartingCollision(scene_, c_.reference, trace_, c_.match, c_.tolerance);
        fits_.push_back({Variant{c_.reference, {}}, c_.match, {}});
        phase_ = Phase::Singles;
        return;
    case Phase::Singles:
        if (next_ < singles_.size()) fitNext(singles_);
        if (next_ < singles_.size()) return;
        next_ = 0;
        if (std::any_of(fits_.begin() + 1, fits_.end(),
                        [](const VariantFit& f) { return f.match.same(); })) {
            finish();
            return;
        }
        // Two mistakes at once, only when one change explains nothing.
        pairs_ = variantsOf(c_.reference, true);
        pairs_.erase(pairs_.begin(),
                     pairs_.begin() + static_cast<std::ptrdiff_t>(singles_.size() + 1));
        phase_ = Phase::Pairs;
        return;
    case Phase::Pairs:
        if (next_ < pairs_.size()) fitNext(pairs_);
        if (next_ == pairs_.size()) finish();
        return;
    case Phase::Done:
        return;
    }
}

// Runs the next of `variants`, keeping one of each set of variants that simulate the same bit
// for bit (the simplest: the list is simplest first).
void TraceComparer::fitNext(const std::vector<Variant>& variants) {
    const Variant& v = variants[next_++];
    RunMatch m = matchRun(scene_, v.settings, trace_, c_.tolerance);
    ++runs_;
    const auto twin = std::find_if(fits_.begin(), fits_.end(),
                                   [&](const VariantFit& f) { return f.match.hash == m.hash; });
    if (twin != fits_.end()) {
        twin->sameAs.push_back(v);
        return;
    }
    fits_.push_back({v, std::move(m), {}});
}

void TraceComparer::finish() {
    auto explains = [](const VariantFit& f) { return f.match.same(); };
    std::stable_sort(fits_.begin() + 1, fits_.end(), fitsBetter);
    for (auto f = fits_.begin() + 1; f != fits_.end(); ++f)
        if (explains(*f)) c_.explaining.push_back(*f);
    // The closest, when none explains: only one that follows the trace further than the
    // reference does.
    if (c_.explaining.empty() && fits_.size() > 1 &&
        fits_[1].match.first().frame > c_.match.first().frame)
        c_.closest = fits_[1];
    phase_ = Phase::Done;
}
