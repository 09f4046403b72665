#include "simulation.h"

#include "collision.h"
#include "peers.h"

#include <algorithm>

namespace {

class EngineSimulation : public Simulation {
  public:
    explicit EngineSimulation(World world) : world_(std::move(world)) {}
    double step() override {
        last_ = world_.step();
        return last_.stepMs;
    }
    const std::vector<Block>& blocks() override { return world_.blocks; }
    double penetration() override { return std::max(last_.maxPenetration, maxOverlap(world_)); }
    int eventCapHits() const override { return last_.eventCapHits; }
    int collisions() const override { return last_.collisions; }
    double time() const override { return world_.time; }

  private:
    World world_;
    StepStats last_;
};

} // namespace

std::unique_ptr<Simulation> makeEngineSimulation(const Scene& scene, Method method, double dt,
                                                 int substeps) {
    World world = makeWorld(scene);
    world.settings.method = method;
    world.settings.dt = dt;
    world.settings.substeps = substeps;
    world.settings.measureOverlap = false; // measured outside the timed step
    return std::make_unique<EngineSimulation>(std::move(world));
}

std::vector<std::string> peerNames() {
    std::vector<std::string> names;
#ifdef SANDBOX_HAVE_BOX2D
    names.push_back("box2d");
#endif
#ifdef SANDBOX_HAVE_CHIPMUNK
    names.push_back("chipmunk");
#endif
    return names;
}

std::unique_ptr<Simulation> makePeerSimulation(const std::string& peer, const Scene& scene,
                                               double dt, int substeps) {
#ifdef SANDBOX_HAVE_BOX2D
    if (peer == "box2d") return makeBox2dSimulation(scene, dt, substeps);
#endif
#ifdef SANDBOX_HAVE_CHIPMUNK
    if (peer == "chipmunk") return makeChipmunkSimulation(scene, dt, substeps);
#endif
    (void)peer, (void)scene, (void)dt, (void)substeps; // unused when no peer is built
    return nullptr;
}

double bruteForcePenetration(const std::vector<Block>& blocks, const Bounds& bounds) {
    double deepest = 0.0;
    for (size_t i = 0; i < blocks.size(); ++i) {
        const Aabb a = aabbOf(blocks[i]);
        deepest = std::max(deepest, outsideDepth(a, bounds));
        for (size_t j = i + 1; j < blocks.size(); ++j)
            if (blocks[i].isDynamic() || blocks[j].isDynamic())
                deepest = std::max(deepest, penetration(a, aabbOf(blocks[j])));
    }
    return deepest;
}
