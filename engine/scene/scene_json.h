// Shared by scene.cpp (error messages), scene_save.cpp (writing) and other JSON file formats
// built on scene files (lessons): JSON values as text, and the scene loader's file reading and
// syntax checks, whose errors name the place (file:line:column).
#pragma once

#include "input_limits.h"
#include "scene_error.h"
#include "vec2.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <vector>

#include <initializer_list>
#include <string>

namespace scene_json {

// One value on one line; invalid UTF-8 (only possible in scenes built in code) is replaced.
// Doubles print in the shortest form that reads back to the same bits.
inline std::string dumpValue(const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

inline std::string numberList(std::initializer_list<double> xs) {
    std::string out = "[";
    for (double x : xs) out += (out.size() > 1 ? ", " : "") + dumpValue(x);
    return out + "]";
}

// A value error at a JSON path ("blocks[3].mass"): thrown by the typed access below, turned into
// a SceneError by the loader that called it.
struct ValueError {
    std::string path;
    std::string message;
};

std::string indexPath(const std::string& path, std::size_t i);        // "blocks" -> "blocks[3]"
std::string keyPath(const std::string& path, const std::string& key); // "world" -> "world.dt"
// Throws for a key of `object` not in `known`.
void checkKeys(const nlohmann::json& object, const std::string& path,
               std::initializer_list<const char*> known);
void checkKeys(const nlohmann::json& object, const std::string& path,
               const std::vector<const char*>& known);
const nlohmann::json& requireObject(const nlohmann::json& value, const std::string& path);
double number(const nlohmann::json& value, const std::string& path); // finite
// A finite number within `range` (input_limits.h); the message names the limit.
double number(const nlohmann::json& value, const std::string& path, const limits::Range& range);
std::string string(const nlohmann::json& value, const std::string& path);
// An array of exactly `n` finite numbers, each within `range` (by default at most 1e9 in size).
std::vector<double> numbers(const nlohmann::json& value, const std::string& path, std::size_t n,
                            const limits::Range& range);
std::vector<double> numbers(const nlohmann::json& value, const std::string& path, std::size_t n);
Vec2 vec2(const nlohmann::json& value, const std::string& path, const limits::Range& range);
Vec2 vec2(const nlohmann::json& value, const std::string& path);

} // namespace scene_json

namespace settings_table {
struct WorldKey;
}
struct BlockDef;
struct WorldSettings;
// A world setting's value as JSON (a scene file's "world" and sandbox-cli run --json).
nlohmann::json settingJson(const settings_table::WorldKey& row, const WorldSettings& s);
// Reads a world setting's value as a scene file's "world" holds it into `s`, within the row's
// limits; throws scene_json::ValueError naming `path` (scene.cpp; the edits of app/edit too).
void readSetting(const settings_table::WorldKey& row, const nlohmann::json& value,
                 const std::string& path, WorldSettings& s);
// A block as a scene file holds it, every field within its limits (a size long enough for its
// position, a force for its mass); throws scene_json::ValueError naming `path` or its fields.
BlockDef parseBlock(const nlohmann::json& value, const std::string& path);
// A block as a scene file writes it (the object parseBlock reads back to the same block).
nlohmann::json blockJson(const BlockDef& block);

// Why `path` cannot be read as a regular file (missing, a directory, a FIFO that could block
// forever), or nothing: the check of every file the sandbox reads (scenes, lessons, traces).
std::optional<SceneError> regularFileError(const std::string& path);
// Reads a regular file of at most the scene format's size limit into `text`.
std::optional<SceneError> readJsonFile(const std::string& path, std::string& text);
// Parses JSON text with the scene loader's checks (size, emptiness, nesting depth, NUL bytes,
// duplicate keys); a syntax error is placed as "source:line:column".
std::optional<SceneError> parseJsonText(const std::string& text, const std::string& sourceName,
                                        nlohmann::json& root);
// True when parseJsonText accepts `text` and its root is an object with `key` (escapes decoded):
// the same answer, but text whose root is not an object, or that has no such key at the root,
// is told apart by one pass of nlohmann's SAX parser, which builds nothing and stops at the root's
// first token when it is not an object; only text that has the key is parsed in full (for every
// check: size, depth, NUL bytes, duplicate keys).
bool jsonRootHasKey(const std::string& text, const std::string& key);
// The scene format's top-level keys: the one list parseScene checks a file's root against.
extern const std::vector<const char*> kSceneKeys;
// The scene's name when `text` reads as a scene file at its top level (JSON whose root is an
// object, every key of it one of kSceneKeys, "name" a string), by the same one SAX pass as
// jsonRootHasKey, which builds nothing; nothing otherwise. The blocks and the world are not
// checked: a file listed by this name may still fail to load, with the loader's error.
std::optional<std::string> sceneNameOf(const std::string& text);
