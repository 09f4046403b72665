// Engine speed on the benchmark gas: ms per step for each method and block count, and the
// perfect method's collisions per second. Run: build/tests/bench/engine_bench
#include "gas.h"
#include "scene.h"
#include "scratch.h"

#include <benchmark/benchmark.h>

namespace {

void stepGas(benchmark::State& state, Method method) {
    World world = makeGas(static_cast<int>(state.range(0)), method);
    for (int i = 0; i < 30; ++i) world.step(); // let the grid start dissolve
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

void BM_Perfect(benchmark::State& state) {
    stepGas(state, Method::Perfect);
}
void BM_MoveAndCorrect(benchmark::State& state) {
    stepGas(state, Method::MoveAndCorrect);
}
void BM_TurnBased(benchmark::State& state) {
    stepGas(state, Method::TurnBased);
}

// The shipped 500-block gas scene (app/scenes/gas_500.json) under each method: the README's
// "collisions per second" figure.
void BM_Gas500Scene(benchmark::State& state) {
    const SceneResult loaded = loadSceneFile(SANDBOX_SCENES_DIR "/gas_500.json");
    if (!loaded.scene) {
        state.SkipWithError(loaded.error.text().c_str());
        return;
    }
    World world = makeWorld(*loaded.scene);
    world.settings.method = static_cast<Method>(state.range(0));
    world.settings.measureOverlap = false;
    long collisions = 0;
    for (auto _ : state) collisions += world.step().collisions;
    state.SetLabel(methodName(world.settings.method));
    state.counters["collisions/s"] =
        benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
}

// Issue 13's event storm (gas.h): every frame is 20,000 events (the cap), so events/s is the
// cost per event at speeds where every block crosses the world about a million times a frame.
// Argument 1: the plain search only (as before windows, issue 13), to compare in one sitting.
void BM_PerfectStorm(benchmark::State& state) {
    World world = makeStorm();
    if (state.range(0) == 1) world.scratch.get().perfect.windowPolicy = -1.0;
    long events = 0;
    for (auto _ : state) events += world.step().events;
    state.counters["events/s"] =
        benchmark::Counter(static_cast<double>(events), benchmark::Counter::kIsRate);
    state.counters["events/step"] =
        benchmark::Counter(static_cast<double>(events), benchmark::Counter::kAvgIterations);
}

} // namespace

BENCHMARK(BM_PerfectStorm)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Gas500Scene)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Perfect)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MoveAndCorrect)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TurnBased)->RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
