#include "cost.h"

#include <algorithm>
#include <chrono>
#include <exception>

void CostMeasurement::measure(const World& world, const std::string& scenePath, int frames) {
    frames = std::max(1, frames);
    for (std::size_t m = 0; m < msPerStep_.size(); ++m) {
        World copy = world;
        copy.settings.method = static_cast<Method>(m);
        copy.settings.measureTime = true; // what this measures
        double total = 0.0;
        for (int i = 0; i < frames; ++i) total += copy.step().stepMs;
        msPerStep_[m] = total / frames;
    }
    measuredScene_ = scenePath;
}

void CostMeasurement::startSweep(Sweep sweep) {
    if (sweepRunning()) return;
#ifdef __EMSCRIPTEN__
    take(sweep); // the browser build has one thread: the sweep runs now (the page waits for it)
#else
    job_ = std::async(std::launch::async, std::move(sweep));
#endif
}

void CostMeasurement::take(const Sweep& sweep) {
    try {
        rows_ = sweep();
        error_.clear();
    } catch (const std::exception& e) {
        error_ = e.what();
    }
}

void CostMeasurement::runSweepNow(const Sweep& sweep) {
    take(sweep);
}

bool CostMeasurement::pollSweep(bool wait) {
    if (!job_.valid()) return false;
    if (!wait && job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    // get() rethrows what the sweep threw; take() turns it into error().
    take([this] { return job_.get(); });
    return true;
}

CostMeasurement::Sweep quickTradeoffSweep(const std::string& scenesDir) {
    TradeoffOptions options;
    options.scenesDir = scenesDir;
    options.quick = true;
    return [options] { return runTradeoff(options); };
}

std::vector<std::string> tradeoffScenes(const std::vector<TradeoffRow>& rows) {
    std::vector<std::string> scenes;
    for (const TradeoffRow& r : rows) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
            scenes.push_back(r.scene);
        }
    }
    return scenes;
}

std::vector<const TradeoffRow*> tradeoffRowsOf(const std::vector<TradeoffRow>& rows,
                                               const std::string& scene) {
    std::vector<const TradeoffRow*> out;
    for (const TradeoffRow& r : rows) {
        if (r.scene == scene) out.push_back(&r);
    }
    std::stable_sort(out.begin(), out.end(), [](const TradeoffRow* a, const TradeoffRow* b) {
        return a->msPerSimulatedSecond < b->msPerSimulatedSecond;
    });
    return out;
}
