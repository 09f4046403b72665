// Saving a scene from the app: the name offered (from the scene's name), the absolute path it is
// written to and remembered by (the settings must find it from any directory), a free name when
// the offered one exists (never overwrite without asking), and an honest note in the description
// when the settings differ from those the description was written for. Pure logic.
#pragma once

#include "scene.h"

#include <functional>
#include <string>

// "Lecture example 1" -> "lecture_example_1" (lower case, runs of other characters as one '_');
// "scene" when nothing is left.
std::string sceneFileStem(const std::string& sceneName);
// `path` made absolute against `cwd` (when relative) and normalised, with ".json" added when it
// has no extension. "" stays "".
std::string absoluteScenePath(const std::string& path, const std::string& cwd);
// The path offered for saving `sceneName` in `dir`: dir/STEM.json, or dir/STEM-2.json, -3, ...
// the first one `exists` says is free (up to -999, then STEM.json again). `extension` ".csv" for
// a plot's export.
std::string suggestSavePath(const std::string& sceneName, const std::string& dir,
                            const std::function<bool(const std::string&)>& exists,
                            const std::string& extension = ".json");
// True when `path` names something on disk (an error reads as false): suggestSavePath's `exists`.
bool pathExists(const std::string& path);
// "" when `now` has the settings `original` has (every scene key of settings_table.h); else one
// sentence naming what changed, in the table's order, e.g.
// "Saved with changed settings: gravity (0, -9.81) m/s², method turn-based."
std::string changedSettingsNote(const WorldSettings& original, const WorldSettings& now);
// The description to save: the original text and, when the settings changed, the note after it
// (the text itself is never rewritten: it may state what no longer holds, the note says why);
// the original alone when the note would take it past the format's limit (input_limits.h).
std::string savedDescription(const std::string& description, const WorldSettings& original,
                             const WorldSettings& now);
// True when the two settings differ in what changedSettingsNote() names.
bool settingsDiffer(const WorldSettings& a, const WorldSettings& b);
// Quitting asks first when the user has edited the blocks, or the settings differ from the
// scene's, since the last load or save.
bool hasUnsavedEdits(bool blocksEdited, const WorldSettings& scene, const WorldSettings& now);
