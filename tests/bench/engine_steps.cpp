// Engine work counted instead of timed (docs/performance.md, issue 37): one of engine_bench's
// workloads stepped a fixed number of times, for valgrind's callgrind, whose instruction counts
// do not depend on the machine's load. Only measuredSteps is counted (not the setup), e.g.
//   valgrind --tool=callgrind --toggle-collect='*measuredSteps*' engine_steps gas perfect 500 50
// Workloads (STEPS steps each): gas METHOD BLOCKS STEPS (BM_Perfect, BM_MoveAndCorrect,
// BM_TurnBased: after their 30 steps), scene METHOD STEPS (BM_Gas500Scene), storm PLAIN STEPS
// (BM_PerfectStorm, PLAIN 1: the plain search). Prints the collisions and the state hash.
#include "gas.h"
#include "scene.h"
#include "scratch.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[gnu::noinline]] long measuredSteps(World& world, int steps) {
    long collisions = 0;
    for (int i = 0; i < steps; ++i) collisions += world.step().collisions;
    return collisions;
}

Method methodArg(const char* name) {
    Method method = Method::Perfect;
    if (!parseMethod(name, method)) {
        std::fprintf(stderr, "engine_steps: unknown method '%s'\n", name);
        std::exit(1);
    }
    return method;
}

} // namespace

int main(int argc, char** argv) {
    const std::string workload = argc > 1 ? argv[1] : "";
    World world;
    int steps = 0;
    if (workload == "gas" && argc == 5) {
        world = makeGas(std::atoi(argv[3]), methodArg(argv[2]));
        for (int i = 0; i < 30; ++i) world.step(); // as engine_bench
        steps = std::atoi(argv[4]);
    } else if (workload == "scene" && argc == 4) {
        const SceneResult loaded = loadSceneFile(SANDBOX_SCENES_DIR "/gas_500.json");
        if (!loaded.scene) {
            std::fprintf(stderr, "engine_steps: %s\n", loaded.error.text().c_str());
            return 1;
        }
        world = makeWorld(*loaded.scene);
        world.settings.method = methodArg(argv[2]);
        world.settings.measureOverlap = false;
        steps = std::atoi(argv[3]);
    } else if (workload == "storm" && argc == 4) {
        world = makeStorm();
        if (std::atoi(argv[2]) == 1) world.scratch.get().perfect.windowPolicy = -1.0;
        steps = std::atoi(argv[3]);
    } else {
        std::fprintf(stderr, "usage: engine_steps gas METHOD BLOCKS STEPS | scene METHOD STEPS | "
                             "storm PLAIN STEPS\n");
        return 1;
    }
    world.step(); // the buffers grown (engine_bench's first iteration)
    const long collisions = measuredSteps(world, steps);
    std::printf("collisions %ld state hash %016llx\n", collisions,
                static_cast<unsigned long long>(stateHash(world)));
    return 0;
}
