// Where the shipped scenes are, and which scene file a command-line argument names, so the
// program works from any directory.
#pragma once

#include <string>
#include <vector>

struct SceneEntry {
    std::string path;  // full path of the .json file
    std::string title; // the scene's name (the file name, underscores as spaces, if it has none)
};

// The file in a scenes directory that lists its scenes in the lecture's order.
constexpr const char* kSceneOrderFile = "lecture_order.txt";

// The directory of the running executable ("" when unknown).
std::string executableDirectory();

// The first existing directory among: `exeDir`/scenes, `exeDir`/../share/collision-sandbox/scenes,
// `builtInDir` (the source tree's app/scenes, compiled in), ./app/scenes, ./scenes.
// "" when none exists.
std::string findScenesDirectory(const std::string& exeDir, const std::string& builtInDir);
// The same search for another folder of shipped files ("lessons": `exeDir`/lessons, ...).
std::string findDataDirectory(const std::string& exeDir, const std::string& builtInDir,
                              const std::string& folder);

// The .json files of `dir`: first those kSceneOrderFile lists, in its order, then the others by
// title.
std::vector<SceneEntry> listScenes(const std::string& dir);

// The file `arg` names: `arg` itself when it exists, else `scenesDir`/`arg`, else
// `scenesDir`/`arg`.json. Returns `arg` unchanged when none exists (the loader then reports it).
std::string resolveScenePath(const std::string& arg, const std::string& scenesDir);

// The scene a plain `sandbox` opens.
constexpr const char* kDefaultSceneFile = "bouncing_squares.json";
