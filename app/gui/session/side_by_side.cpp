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

void MethodsSideBySide::step(const WorldSettings& live, int pushed, Vec2 thrust) {
    if (!running) return;
    for (std::size_t m = 0; m < runs.size(); ++m) {
        MethodRun& r = runs[m];
        r.world.settings = live;
        r.world.settings.method = static_cast<Method>(m);
        const bool push = pushed >= 0 && static_cast<std::size_t>(pushed) < r.world.blocks.size() &&
                          r.world.blocks[static_cast<std::size_t>(pushed)].isDynamic();
        Vec2 own;
        if (push) {
            Block& b = r.world.blocks[static_cast<std::size_t>(pushed)];
            own = b.force;
            b.force = own + thrust;
        }
        r.stats = r.world.step();
        if (push) r.world.blocks[static_cast<std::size_t>(pushed)].force = own;
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
