// Scene files, format v1 (docs/scene-format.md): load with validation, save, and build a World from
// a scene.
#pragma once

#include "block_def.h"
#include "player.h"
#include "scene_error.h"
#include "world.h"

#include <optional>
#include <string>
#include <vector>

struct Scene {
    std::string name;
    std::string description;
    // s, optional: how long the scene is meant to be watched (it has made its point by then, e.g.
    // before a wall hit spoils a conservation law). The app pauses there once; `sandbox-cli run`
    // without --steps or --time simulates this long. None: the scene runs on.
    std::optional<double> duration;
    Bounds bounds;
    WorldSettings settings = defaultWorldSettings();
    std::vector<BlockDef> blocks;
    // The block the keys control (player.h), optional: "player" names it, with its push and jump.
    std::optional<PlayerDef> player;

    bool operator==(const Scene& o) const;
};

struct SceneResult {
    std::optional<Scene> scene;
    SceneError error; // meaningful only when !scene
};

// Parses and validates scene text; `sourceName` is used in error places.
SceneResult parseScene(const std::string& text, const std::string& sourceName);
SceneResult loadSceneFile(const std::string& path);
std::string sceneToJson(const Scene& scene);
// Writes to a temporary file beside `path` and renames it, so a failed save loses nothing.
bool saveSceneFile(const Scene& scene, const std::string& path, std::string* error);

World makeWorld(const Scene& scene);
// The current state of `world` as a scene, keeping from `original` what a world does not hold:
// the name, description and duration, the blocks' names and colours, and the player.
Scene sceneFromWorld(const World& world, const Scene& original);
// One block of the world from its file form (a static block still, a kinematic one and a static
// one of infinite mass), and back (without its name and colour, which the world does not hold).
Block makeBlock(const BlockDef& def);
BlockDef blockDefOf(const Block& block);
// Why block `index` of the world may not stand where it is, as a scene file would refuse it
// ("sticks out of the world bounds [...]", "overlaps blocks[2]": touching is fine, static blocks
// may overlap each other); "" when it may.
std::string placementProblem(const World& world, std::size_t index);
