#include "simulation.h"

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
