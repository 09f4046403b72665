// `sandbox-cli compare` and the app's "Open a trace": a student's trace against the reference
// (the scene under its settings, the Tips slides' mistakes off), the first difference, the
// reference's collision nearest before it, and a diagnosis: which variant of the reference (the
// methods, the mistakes, the resolves, the integrators) reproduces the trace best and how
// closely, and what the trace shows at the collision where the two part. Below the CLI and the
// GUI: no ImGui, no output streams.
#pragma once

#include "parting.h"
#include "variants.h"

#include <optional>
#include <string>
#include <vector>

// A variant run against the trace.
struct VariantFit {
    Variant variant;
    RunMatch match;
    std::vector<Variant> sameAs; // variants that simulate bit for bit the same
};

struct TraceComparison {
    WorldSettings reference; // the settings compared with
    Tolerance tolerance;
    std::int64_t frames = 0;            // rows of the trace
    RunMatch match;                     // the trace against the reference
    PartingCollision parting;           // where they part (when they do)
    std::vector<VariantFit> explaining; // variants within the tolerance over the whole trace,
                                        // best (smallest position error) first
    std::optional<VariantFit> closest;  // when none explains: the one that follows the trace
                                        // longest (then with the smallest error)
    std::vector<std::string> notes;     // what the comparison assumed (the scene's mistakes off)
    bool same() const { return match.same(); }
};

// The reference's settings for `scene`: its own, the Tips slides' mistakes off (a mistake_*
// scene shows a mistake; the reference is the engine without it), and `method` when given.
WorldSettings referenceSettings(const Scene& scene, std::optional<Method> method);

// Compares `trace` with `scene` under `reference`. Every variant is simulated only when the trace
// differs from the reference.
TraceComparison compareTrace(const Scene& scene, const WorldSettings& reference, const Trace& trace,
                             const Tolerance& tolerance);

// compareTrace one simulated run at a time, the same result: step() until done(), then take().
// The browser runs one step a frame, so its page answers keys between them (issue 41). The
// scene and the trace must outlive it.
class TraceComparer {
  public:
    TraceComparer(const Scene& scene, const WorldSettings& reference, const Trace& trace,
                  const Tolerance& tolerance);
    bool done() const { return phase_ == Phase::Done; }
    void step(); // the next run (the reference first, then the variants)
    int runsDone() const { return runs_; }
    // The runs planned so far (the pairs of mistakes join only when no single change explains).
    int runsPlanned() const;
    TraceComparison take() { return std::move(c_); }

  private:
    enum class Phase { Reference, Singles, Pairs, Done };
    void fitNext(const std::vector<Variant>& variants);
    void finish();
    const Scene& scene_;
    const Trace& trace_;
    TraceComparison c_;
    Phase phase_ = Phase::Reference;
    std::vector<Variant> singles_, pairs_;
    std::vector<VariantFit> fits_;
    std::size_t next_ = 0; // in singles_ or pairs_
    int runs_ = 0;
};
