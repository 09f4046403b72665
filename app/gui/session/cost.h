// Speed versus accuracy in the app, as logic (the cost overlay draws it): the current scene's
// cost per step under each method, measured on a copy of the world, and the tradeoff sweep
// (runTradeoff, quick) run on a background thread that the frame only polls. Owned by App.
#pragma once

#include "tradeoff.h"
#include "world.h"

#include <array>
#include <functional>
#include <future>
#include <string>
#include <vector>

// Frames each method steps the copy for one measurement.
constexpr int kCostFrames = 30;

class CostMeasurement {
  public:
    using Sweep = std::function<std::vector<TradeoffRow>()>;

    CostMeasurement() { msPerStep_.fill(-1.0); }

    // True when the last measurement was of `scenePath`.
    bool measured(const std::string& scenePath) const { return measuredScene_ == scenePath; }
    // Steps a copy of `world` `frames` frames under each method (the world itself is untouched)
    // and keeps the mean ms per step of each.
    void measure(const World& world, const std::string& scenePath, int frames = kCostFrames);
    // ms per step under `method` in the last measurement; negative before any.
    double msPerStep(Method method) const { return msPerStep_[static_cast<std::size_t>(method)]; }

    // Starts `sweep` on a background thread (nothing when one is running).
    void startSweep(Sweep sweep);
    // Runs `sweep` now, on this thread (a screenshot shows the chart).
    void runSweepNow(const Sweep& sweep);
    bool sweepRunning() const { return job_.valid(); }
    // Takes the background sweep's result when it is ready (called every frame); true when it
    // did. `wait`: blocks until it is.
    bool pollSweep(bool wait = false);
    // The last sweep's rows, and its error (the exception's message) when it failed.
    const std::vector<TradeoffRow>& rows() const { return rows_; }
    const std::string& error() const { return error_; }

    int chartScene = 0; // which of tradeoffScenes(rows()) the chart shows (the overlay's choice)

  private:
    void take(const Sweep& sweep);

    std::string measuredScene_;
    std::array<double, static_cast<std::size_t>(Method::Count)> msPerStep_; // negative: none
    std::future<std::vector<TradeoffRow>> job_;
    std::vector<TradeoffRow> rows_;
    std::string error_;
};

// The quick sweep over the shipped scenes in `scenesDir`.
CostMeasurement::Sweep quickTradeoffSweep(const std::string& scenesDir);
// The scenes of `rows`, in the order they first appear.
std::vector<std::string> tradeoffScenes(const std::vector<TradeoffRow>& rows);
// The rows of `scene`, cheapest first (the chart's lines run left to right).
std::vector<const TradeoffRow*> tradeoffRowsOf(const std::vector<TradeoffRow>& rows,
                                               const std::string& scene);
