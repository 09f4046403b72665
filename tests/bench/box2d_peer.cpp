// Box2D 2.4 on the same gas as the engine benchmark, through the analysis library's peer
// (fixed rotation, zero friction, restitution 1, dt 1/60, 8 velocity and 3 position iterations).
#include "gas.h"
#include "simulation.h"

#include <benchmark/benchmark.h>

namespace {

double kineticEnergy(const std::vector<Block>& blocks) {
    double e = 0.0;
    for (const Block& b : blocks) e += 0.5 * b.mass * lengthSquared(b.velocity);
    return e;
}

void BM_Box2D(benchmark::State& state) {
    auto sim =
        makePeerSimulation("box2d", makeGasScene(static_cast<int>(state.range(0))), 1.0 / 60.0, 1);
    const double startEnergy = kineticEnergy(sim->blocks());
    for (int i = 0; i < 30; ++i) sim->step();
    for (auto _ : state) sim->step();
    // Accuracy alongside speed: the relative change of kinetic energy over the run.
    state.counters["energy_drift"] = (kineticEnergy(sim->blocks()) - startEnergy) / startEnergy;
}

} // namespace

BENCHMARK(BM_Box2D)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);
