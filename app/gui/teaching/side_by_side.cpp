#include "side_by_side.h"

#include <algorithm>
#include <cmath>

void MethodsSideBySide::start(const World& world) {
    for (std::size_t m = 0; m < runs.size(); ++m) {
        runs[m] = MethodRun{};
        runs[m].world = world;
        runs[m].world.settings.method = static_cast<Method>(m);
    }
    running = true;
}

void MethodsSideBySide::step(const WorldSettings& live) {
    if (!running) return;
    for (std::size_t m = 0; m < runs.size(); ++m) {
        MethodRun& r = runs[m];
        r.world.settings = live;
        r.world.settings.method = static_cast<Method>(m);
        r.stats = r.world.step();
        addStep(r.totals, r.stats);
    }
}

double MethodsSideBySide::divergence(Method method) const {
    const World& a = run(method).world;
    const World& p = run(Method::Perfect).world;
    double worst = 0.0;
    const std::size_t n = std::min(a.blocks.size(), p.blocks.size());
    for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, length(a.blocks[i].position - p.blocks[i].position));
    }
    return worst;
}
