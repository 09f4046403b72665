// libFuzzer target on the scene loader (issue 7): any bytes given to parseScene must come back as
// a scene or a placed error, never a crash, a hang, undefined behaviour or a leak. A scene that
// loads must also build a world, survive a save/load round trip unchanged, and step once.
#include "scene.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const SceneResult result = parseScene(text, "fuzz");
    if (!result.scene) {
        // Every error names its place.
        if (result.error.where.empty() || result.error.message.empty()) std::abort();
        return 0;
    }
    const Scene& scene = *result.scene;
    // Round trip: what the saver writes loads back to the same scene.
    const SceneResult again = parseScene(sceneToJson(scene), "fuzz-roundtrip");
    if (!again.scene || !(*again.scene == scene)) std::abort();
    // A loaded scene is a valid world: one small step must be fine (bounded: few blocks only).
    if (scene.blocks.size() <= 64) {
        World world = makeWorld(scene);
        world.settings.eventCap = 1000;
        world.step();
    }
    return 0;
}
