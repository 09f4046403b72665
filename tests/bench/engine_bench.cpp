// Engine speed on the benchmark gas: ms per step for each method and block count, and the
// perfect method's collisions per second. Run: build/tests/bench/engine_bench
#include "gas.h"

#include <benchmark/benchmark.h>

namespace {

void stepGas(benchmark::State& state, Method method) {
    World world = makeGas(static_cast<int>(state.range(0)), method);
    for (int i = 0; i < 30; ++i) world.step();  // let the grid start dissolve
    const double startEnergy = kineticEnergy(world);
    long collisions = 0;
    for (auto _ : state) collisions += world.step().collisions;
    // Accuracy alongside speed: the relative change of kinetic energy over the run (C = 1).
    state.counters["energy_drift"] = (kineticEnergy(world) - startEnergy) / startEnergy;
    state.counters["collisions/s"] =
        benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
    state.counters["collisions/step"] =
        benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kAvgIterations);
}

void BM_Perfect(benchmark::State& state) { stepGas(state, Method::Perfect); }
void BM_MoveAndCorrect(benchmark::State& state) { stepGas(state, Method::MoveAndCorrect); }
void BM_TurnBased(benchmark::State& state) { stepGas(state, Method::TurnBased); }

}  // namespace

BENCHMARK(BM_Perfect)->RangeMultiplier(10)->Range(100, 100000)->Arg(500)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MoveAndCorrect)->RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TurnBased)->RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
