// The peers on the same gas as the engine benchmark, through the analysis library: Box2D 2.4
// (fixed rotation, zero friction, restitution 1, dt 1/60, 8 velocity and 3 position iterations)
// and Chipmunk 7 (infinite moment, zero friction, elasticity 1, 10 iterations), when installed.
#include "gas.h"
#include "simulation.h"

#include <benchmark/benchmark.h>

namespace {

double kineticEnergy(const std::vector<Block>& blocks) {
    double e = 0.0;
    for (const Block& b : blocks) e += 0.5 * b.mass * lengthSquared(b.velocity);
    return e;
}

void stepPeer(benchmark::State& state, const char* peer) {
    const Scene gas = makeGasScene(static_cast<int>(state.range(0)));
    auto sim = makePeerSimulation(peer, gas, 1.0 / 60.0, 1);
    if (!sim) {
        state.SkipWithError("this peer was not built (its Debian package is missing)");
        return;
    }
    const double startEnergy = kineticEnergy(sim->blocks());
    for (int i = 0; i < 30; ++i) sim->step();
    for (auto _ : state) sim->step();
    // Accuracy alongside speed: the relative change of kinetic energy over the run.
    state.counters["energy_drift"] = (kineticEnergy(sim->blocks()) - startEnergy) / startEnergy;
}

void BM_Box2D(benchmark::State& state) {
    stepPeer(state, "box2d");
}
void BM_Chipmunk(benchmark::State& state) {
    stepPeer(state, "chipmunk");
}

} // namespace

BENCHMARK(BM_Box2D)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Chipmunk)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);
