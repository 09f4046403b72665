// Every change to the world is an Edit (docs/edits.md): set a world key, set a block's field,
// add a block, remove one. Keys and limits come from the settings table (settings_table.h): a
// value is read exactly as a scene file's would be, so a new world key or block field needs no
// change here. applyEdit checks an edit and applies it, or refuses it and changes nothing; what
// it returns undoes it exactly (undoEdit) and does it again (redoEdit). Below both sandbox-cli
// and the GUI: the engine only.
#pragma once

#include "block_def.h"
#include "world.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// What each block is called and how it is coloured; parallel to world.blocks (the engine's Block
// has no name), kept in step when blocks are added or removed.
struct BlockLabel {
    std::string name;
    std::string color; // "#rrggbb" or "" for the palette
};

// Which block an edit is about: by its place (blocks[2], as the error messages write it) or by
// its name (the one block of that name).
struct BlockRef {
    int index = -1;   // >= 0: blocks[index]
    std::string name; // index < 0: the block called this
};
// "blocks[2]" or the name.
std::string refText(const BlockRef& ref);
// "blocks[2]" is the place, anything else a name.
BlockRef parseRef(const std::string& text);

// A value as a scene file writes it (an nlohmann::json, null by default), held through a pointer
// so that this header, which most of the app includes through the lesson and the edit log, needs
// only json_fwd.hpp: json.hpp is ~25,000 lines to compile in every file (build time). `*value`
// is the json; a copy copies it. Empty (no pointer) is the null json.
class JsonValue {
  public:
    JsonValue() = default;
    JsonValue(nlohmann::json value); // implicit, as a json is from its values
    JsonValue(const JsonValue& other);
    JsonValue(JsonValue&& other) noexcept;
    JsonValue& operator=(const JsonValue& other);
    JsonValue& operator=(JsonValue&& other) noexcept;
    ~JsonValue();
    const nlohmann::json& operator*() const;
    nlohmann::json& operator*();
    const nlohmann::json* operator->() const { return &**this; }
    nlohmann::json* operator->() { return &**this; }

  private:
    nlohmann::json* json_ = nullptr; // owned; null: the null json
};

struct Edit {
    enum class Kind : std::uint8_t { SetWorld, SetBlock, Add, Remove };
    Kind kind = Kind::SetWorld;
    std::string key; // SetWorld: a world key ("bounciness"); SetBlock: a block field ("mass")
    BlockRef block;  // SetBlock, Remove
    // SetWorld, SetBlock: the value as a scene file writes it (null: a block's own value, such
    // as its friction, back to the world's); Add: the block as a scene file writes it.
    JsonValue value;

    static Edit setWorld(const std::string& key, nlohmann::json value);
    static Edit setBlock(BlockRef block, const std::string& field, nlohmann::json value);
    static Edit add(nlohmann::json block);
    static Edit remove(BlockRef block);
};

// The key a log line's "set" writes: "bounciness", "m2.mass", "blocks[1].mass"; for an add
// "add", for a remove the block.
std::string editKey(const Edit& edit);

// A refused edit: the key it names and why ("m2.mass", "must be from 1e-15 to 1e15 kg, not -4").
struct EditError {
    std::string key;
    std::string message;
    bool empty() const { return message.empty(); }
    std::string text() const { return key.empty() ? message : key + ": " + message; }
};

// What an edit acts on: the world and its blocks' names and colours (parallel to world.blocks).
struct EditTarget {
    World& world;
    std::vector<BlockLabel>& labels;
};

// An applied edit and what undoes it: the values before and after, exactly.
struct AppliedEdit {
    Edit edit;                                   // as asked
    int index = -1;                              // SetBlock, Add, Remove: the block's place
    WorldSettings settingsBefore, settingsAfter; // SetWorld
    // SetBlock: the block as a scene file holds it before and after (the fields that differ are
    // what undo and redo put back); Add: after; Remove: before.
    BlockDef before, after;
    Block removed; // Remove: the block as it was, exactly (its velocity, its kind's mass)
};

struct ApplyResult {
    std::optional<AppliedEdit> applied;
    EditError error; // when not applied
};

// Applies `edit` to `target`: the value read as a scene file reads it (the table's limits), a
// moved or resized block inside the bounds and overlapping no other (as a scene file must), the
// block found by its place or by its name (exactly one block of that name).
ApplyResult applyEdit(EditTarget target, const Edit& edit);
// Undoes what `applied` did (only what it changed: a block's mass edit does not move it back),
// or does it again. Refused when the block would now overlap another (it moved there since).
EditError undoEdit(EditTarget target, const AppliedEdit& applied);
EditError redoEdit(EditTarget target, const AppliedEdit& applied);
// Two edits of one gesture (a slider or a block dragged) as one: `first`'s before, `next`'s
// after. False when they are not of the same key and block.
bool joinEdits(AppliedEdit& first, const AppliedEdit& next);
