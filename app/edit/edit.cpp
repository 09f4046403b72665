// Edits applied, undone and done again (edit.h). A value goes through the scene reader
// (readSetting, parseBlock): the same limits and messages as a scene file's.
#include "edit.h"

#include "printable.h"
#include "scene.h"
#include "scene_json.h"
#include "settings_table.h"

#include <cstdio>
#include <cstdlib>
#include <utility>

JsonValue::JsonValue(nlohmann::json value) : json_(new nlohmann::json(std::move(value))) {}
JsonValue::JsonValue(const JsonValue& other)
    : json_(other.json_ ? new nlohmann::json(*other.json_) : nullptr) {}
JsonValue::JsonValue(JsonValue&& other) noexcept : json_(std::exchange(other.json_, nullptr)) {}
JsonValue& JsonValue::operator=(const JsonValue& other) {
    if (this != &other) *this = JsonValue(other);
    return *this;
}
JsonValue& JsonValue::operator=(JsonValue&& other) noexcept {
    if (this != &other) {
        delete json_;
        json_ = std::exchange(other.json_, nullptr);
    }
    return *this;
}
JsonValue::~JsonValue() {
    delete json_;
}
const nlohmann::json& JsonValue::operator*() const {
    static const nlohmann::json null;
    return json_ ? *json_ : null;
}
nlohmann::json& JsonValue::operator*() {
    if (!json_) json_ = new nlohmann::json();
    return *json_;
}

namespace {

using json = nlohmann::json;

// The block `ref` names, or -1 and why not.
int resolve(const EditTarget& t, const BlockRef& ref, std::string& why) {
    const int count = static_cast<int>(t.world.blocks.size());
    if (ref.index >= 0) {
        if (ref.index < count) return ref.index;
        why = "no such block: the world has " + std::to_string(count) +
              (count == 1 ? " block" : " blocks");
        return -1;
    }
    int found = -1, named = 0;
    for (int i = 0; i < count && i < static_cast<int>(t.labels.size()); ++i) {
        if (t.labels[static_cast<std::size_t>(i)].name != ref.name) continue;
        if (named++ == 0) found = i;
    }
    if (named == 1) return found;
    why = named == 0 ? "no block is named \"" + printable(ref.name) + "\""
                     : std::to_string(named) + " blocks are named \"" + printable(ref.name) +
                           "\": name it by its place, e.g. " +
                           scene_json::indexPath("blocks", static_cast<std::size_t>(found));
    return -1;
}

BlockLabel labelAt(const EditTarget& t, int i) {
    const auto k = static_cast<std::size_t>(i);
    return k < t.labels.size() ? t.labels[k] : BlockLabel{};
}

// Block i as a scene file holds it, with its name and colour.
BlockDef defAt(const EditTarget& t, int i) {
    BlockDef def = blockDefOf(t.world.blocks[static_cast<std::size_t>(i)]);
    const BlockLabel label = labelAt(t, i);
    def.name = label.name;
    def.color = label.color;
    return def;
}

void putAt(EditTarget& t, int i, const BlockDef& def) {
    const auto k = static_cast<std::size_t>(i);
    t.world.blocks[k] = makeBlock(def);
    if (t.labels.size() <= k) t.labels.resize(k + 1);
    t.labels[k] = {def.name, def.color};
}

void insertAt(EditTarget& t, int i, const Block& block, const BlockLabel& label) {
    const auto k = static_cast<std::size_t>(i);
    t.world.blocks.insert(t.world.blocks.begin() + i, block);
    if (t.labels.size() < k) t.labels.resize(k);
    t.labels.insert(t.labels.begin() + i, label);
}

void eraseAt(EditTarget& t, int i) {
    const auto k = static_cast<std::size_t>(i);
    t.world.blocks.erase(t.world.blocks.begin() + i);
    if (k < t.labels.size()) t.labels.erase(t.labels.begin() + i);
}

// Block i may not stand where it is: why (placementProblem), or "".
bool misplaced(const EditTarget& t, int i, std::string& why) {
    why = placementProblem(t.world, static_cast<std::size_t>(i));
    return !why.empty();
}

// Block i set to `next` (a file's form) where it moved, grew or changed kind only if it still
// fits; the block as it was when it does not.
std::string putChecked(EditTarget& t, int i, const BlockDef& next) {
    const Block was = t.world.blocks[static_cast<std::size_t>(i)];
    const BlockLabel label = labelAt(t, i);
    putAt(t, i, next);
    const Block& now = t.world.blocks[static_cast<std::size_t>(i)];
    std::string why;
    if ((now.position != was.position || now.size != was.size || now.kind != was.kind) &&
        misplaced(t, i, why)) {
        t.world.blocks[static_cast<std::size_t>(i)] = was;
        t.labels[static_cast<std::size_t>(i)] = label;
    }
    return why;
}

// `onto` with the fields in which `from` and `to` differ taken from `to` (a file's form, so
// each table row counts: a new block field needs nothing here).
BlockDef withChanges(const BlockDef& onto, const BlockDef& from, const BlockDef& to) {
    json out = blockJson(onto);
    const json a = blockJson(from), b = blockJson(to);
    for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
        const bool inA = a.contains(row.key), inB = b.contains(row.key);
        if (inA == inB && (!inA || a[row.key] == b[row.key])) continue;
        if (inB)
            out[row.key] = b[row.key];
        else
            out.erase(row.key);
    }
    return parseBlock(out, "block");
}

ApplyResult refused(const Edit& edit, std::string message) {
    ApplyResult r;
    r.error = {editKey(edit), std::move(message)};
    return r;
}

ApplyResult setWorld(EditTarget& t, const Edit& edit) {
    const settings_table::WorldKey* row = settings_table::findWorldKey(edit.key);
    if (!row) return refused(edit, "no such world key");
    WorldSettings next = t.world.settings;
    // The value replaces the old one whole (a set of names too), as a scene file's would.
    settings_table::copy(*row, defaultWorldSettings(), next);
    try {
        readSetting(*row, *edit.value, edit.key, next);
    } catch (const scene_json::ValueError& e) {
        return refused(edit, e.message);
    }
    AppliedEdit a;
    a.edit = edit;
    a.settingsBefore = t.world.settings;
    a.settingsAfter = next;
    t.world.settings = next;
    return {a, {}};
}

// The block `edit` names, as it is before the edit; refused when there is none.
ApplyResult named(EditTarget& t, const Edit& edit) {
    std::string why;
    const int i = resolve(t, edit.block, why);
    if (i < 0) return refused(edit, why);
    AppliedEdit a;
    a.edit = edit;
    a.index = i;
    a.before = defAt(t, i);
    return {a, {}};
}

ApplyResult setBlock(EditTarget& t, const Edit& edit) {
    ApplyResult r = named(t, edit);
    if (!r.applied) return r;
    AppliedEdit& a = *r.applied;
    const int i = a.index;
    json block = blockJson(a.before);
    // The row's value as a scene file holds it; null: none, as if the file left it out (a
    // block's own friction then is the world's).
    if (edit.value->is_null())
        block.erase(edit.key);
    else
        block[edit.key] = *edit.value;
    try { // an unknown field is refused as in a file: "m2.weight: unknown key"
        a.after = parseBlock(block, refText(edit.block));
    } catch (const scene_json::ValueError& e) {
        ApplyResult refusal;
        refusal.error = {e.path, e.message};
        return refusal;
    }
    if (std::string problem = putChecked(t, i, a.after); !problem.empty())
        return refused(edit, problem);
    a.after = defAt(t, i); // as the world holds it (a static block stands still)
    return r;
}

ApplyResult add(EditTarget& t, const Edit& edit) {
    AppliedEdit a;
    a.edit = edit;
    try {
        a.after = parseBlock(*edit.value, "add");
    } catch (const scene_json::ValueError& e) {
        ApplyResult r;
        r.error = {e.path, e.message};
        return r;
    }
    a.index = static_cast<int>(t.world.blocks.size());
    insertAt(t, a.index, makeBlock(a.after), {a.after.name, a.after.color});
    std::string why;
    if (misplaced(t, a.index, why)) {
        eraseAt(t, a.index);
        return refused(edit, why);
    }
    a.after = defAt(t, a.index);
    return {a, {}};
}

ApplyResult remove(EditTarget& t, const Edit& edit) {
    ApplyResult r = named(t, edit);
    if (!r.applied) return r;
    r.applied->removed = t.world.blocks[static_cast<std::size_t>(r.applied->index)];
    eraseAt(t, r.applied->index);
    return r;
}

// Puts back a removed block (undo a remove, redo an add) if it still fits.
EditError reinsert(EditTarget& t, const AppliedEdit& a, const Block& block, const BlockDef& def) {
    if (a.index > static_cast<int>(t.world.blocks.size()))
        return {editKey(a.edit), "the world has fewer blocks than it had"};
    insertAt(t, a.index, block, {def.name, def.color});
    std::string why;
    if (!misplaced(t, a.index, why)) return {};
    eraseAt(t, a.index);
    return {editKey(a.edit), why};
}

// Undo (`back`) or redo a block's fields: those the edit changed, from one side to the other.
EditError redoFields(EditTarget& t, const AppliedEdit& a, bool back) {
    if (a.index >= static_cast<int>(t.world.blocks.size()))
        return {editKey(a.edit), "the world has fewer blocks than it had"};
    const BlockDef& from = back ? a.after : a.before;
    const BlockDef& to = back ? a.before : a.after;
    try {
        const BlockDef next = withChanges(defAt(t, a.index), from, to);
        return {editKey(a.edit), putChecked(t, a.index, next)};
    } catch (const scene_json::ValueError& e) { // a field read back: cannot fail
        return {editKey(a.edit), e.message};
    }
}

EditError undoOrRedo(EditTarget& t, const AppliedEdit& a, bool back) {
    switch (a.edit.kind) {
    case Edit::Kind::SetWorld: {
        const settings_table::WorldKey* row = settings_table::findWorldKey(a.edit.key);
        if (row)
            settings_table::copy(*row, back ? a.settingsBefore : a.settingsAfter, t.world.settings);
        return {};
    }
    case Edit::Kind::SetBlock:
        return redoFields(t, a, back);
    case Edit::Kind::Add:
        if (back) {
            if (a.index >= static_cast<int>(t.world.blocks.size()))
                return {editKey(a.edit), "the added block is gone"};
            eraseAt(t, a.index);
            return {};
        }
        return reinsert(t, a, makeBlock(a.after), a.after);
    case Edit::Kind::Remove:
        if (back) return reinsert(t, a, a.removed, a.before);
        if (a.index >= static_cast<int>(t.world.blocks.size()))
            return {editKey(a.edit), "the world has fewer blocks than it had"};
        eraseAt(t, a.index);
        return {};
    }
    return {};
}

} // namespace

std::string refText(const BlockRef& ref) {
    return ref.index >= 0 ? scene_json::indexPath("blocks", static_cast<std::size_t>(ref.index))
                          : ref.name;
}

BlockRef parseRef(const std::string& text) {
    BlockRef ref;
    const std::string prefix = "blocks[";
    if (text.size() > prefix.size() + 1 && text.compare(0, prefix.size(), prefix) == 0 &&
        text.back() == ']') {
        const std::string digits = text.substr(prefix.size(), text.size() - prefix.size() - 1);
        const bool allDigits = digits.size() <= 9 &&
                               digits.find_first_not_of("0123456789") == std::string::npos &&
                               (digits.size() == 1 || digits[0] != '0');
        if (allDigits) {
            ref.index = std::atoi(digits.c_str());
            return ref;
        }
    }
    ref.name = text;
    return ref;
}

Edit Edit::setWorld(const std::string& key, nlohmann::json value) {
    Edit e;
    e.kind = Kind::SetWorld;
    e.key = key;
    e.value = std::move(value);
    return e;
}

Edit Edit::setBlock(BlockRef block, const std::string& field, nlohmann::json value) {
    Edit e;
    e.kind = Kind::SetBlock;
    e.block = std::move(block);
    e.key = field;
    e.value = std::move(value);
    return e;
}

Edit Edit::add(nlohmann::json block) {
    Edit e;
    e.kind = Kind::Add;
    e.value = std::move(block);
    return e;
}

Edit Edit::remove(BlockRef block) {
    Edit e;
    e.kind = Kind::Remove;
    e.block = std::move(block);
    return e;
}

std::string editKey(const Edit& edit) {
    switch (edit.kind) {
    case Edit::Kind::SetWorld:
        return edit.key;
    case Edit::Kind::SetBlock:
        return refText(edit.block) + "." + edit.key;
    case Edit::Kind::Add:
        return "add";
    case Edit::Kind::Remove:
        return refText(edit.block);
    }
    return edit.key;
}

ApplyResult applyEdit(EditTarget target, const Edit& edit) {
    switch (edit.kind) {
    case Edit::Kind::SetWorld:
        return setWorld(target, edit);
    case Edit::Kind::SetBlock:
        return setBlock(target, edit);
    case Edit::Kind::Add:
        return add(target, edit);
    case Edit::Kind::Remove:
        return remove(target, edit);
    }
    return refused(edit, "unknown edit");
}

EditError undoEdit(EditTarget target, const AppliedEdit& applied) {
    return undoOrRedo(target, applied, true);
}

EditError redoEdit(EditTarget target, const AppliedEdit& applied) {
    return undoOrRedo(target, applied, false);
}

bool joinEdits(AppliedEdit& first, const AppliedEdit& next) {
    const Edit::Kind kind = first.edit.kind;
    if (kind != next.edit.kind || first.edit.key != next.edit.key || first.index != next.index ||
        (kind != Edit::Kind::SetWorld && kind != Edit::Kind::SetBlock))
        return false;
    first.edit = next.edit;
    first.settingsAfter = next.settingsAfter;
    first.after = next.after;
    return true;
}
