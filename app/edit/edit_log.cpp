// The edit log read and written, and --set (edit_log.h, docs/edits.md).
#include "edit_log.h"

#include "input_limits.h"
#include "printable.h"
#include "scene_json.h"
#include "settings_table.h"

#include <algorithm>
#include <cmath>

namespace {

using json = nlohmann::json;

bool isBlockField(const std::string& key) {
    const auto rows = settings_table::blockKeys();
    return std::any_of(rows.begin(), rows.end(),
                       [&](const settings_table::BlockKey& row) { return key == row.key; });
}

std::string worldKeyNames() {
    std::string out;
    for (const settings_table::WorldKey* row : settings_table::cliOrder())
        out += (out.empty() ? "" : ", ") + std::string(row->key);
    return out;
}

std::string blockFieldNames() {
    std::string out;
    for (const settings_table::BlockKey& row : settings_table::blockKeys())
        out += (out.empty() ? "" : ", ") + std::string(row.key);
    return out;
}

// ---- --set's value: text read as the row's kind reads it ----

enum class Shape { Number, Pair, NumberOrPair, Names, Name, NumberOrName, Own };

Shape worldShape(settings_table::Kind kind) {
    using settings_table::Kind;
    switch (kind) {
    case Kind::Number:
    case Kind::Whole:
        return Shape::Number;
    case Kind::Pair:
        return Shape::Pair;
    case Kind::NameSet:
        return Shape::Names;
    case Kind::Choice:
    case Kind::Flag:
        return Shape::Name;
    }
    return Shape::Name;
}

Shape blockShape(settings_table::BlockKind kind) {
    using settings_table::BlockKind;
    switch (kind) {
    case BlockKind::Pair:
    case BlockKind::Force:
        return Shape::Pair;
    case BlockKind::Size:
        return Shape::NumberOrPair;
    case BlockKind::Mass:
        return Shape::NumberOrName;
    case BlockKind::Own:
        return Shape::Own;
    case BlockKind::Text:
    case BlockKind::Color:
        return Shape::Name;
    }
    return Shape::Name;
}

// A number when the text is one (parseNumber: what flags accept), else the text (refused by the
// reader with the row's words).
json numberOrText(const std::string& text) {
    double v = 0.0;
    return limits::parseNumber(text, v) ? json(v) : json(text);
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t comma = text.find(','); comma != std::string::npos;
         comma = text.find(',', start)) {
        parts.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    parts.push_back(text.substr(start));
    return parts;
}

json textValue(const std::string& text, Shape shape) {
    switch (shape) {
    case Shape::Number:
        return numberOrText(text);
    case Shape::NumberOrName:
        return numberOrText(text);
    case Shape::Own:
        return text == "none" ? json(nullptr) : numberOrText(text);
    case Shape::Pair:
    case Shape::NumberOrPair: {
        if (!text.empty() && text[0] == '[') {
            json v = json::parse(text, nullptr, false);
            return v.is_discarded() ? json(text) : v;
        }
        const std::vector<std::string> parts = splitCommas(text);
        if (parts.size() == 1 && shape == Shape::NumberOrPair) return numberOrText(text);
        if (parts.size() != 2) return json(text);
        return json::array({numberOrText(parts[0]), numberOrText(parts[1])});
    }
    case Shape::Names: {
        json names = json::array();
        if (text == "none") return names;
        for (const std::string& name : splitCommas(text)) names.push_back(name);
        return names;
    }
    case Shape::Name:
        return json(text);
    }
    return json(text);
}

// The shape of the value `key` (a world key or BLOCK.FIELD) takes, if it is one.
std::optional<Shape> shapeOfKey(const std::string& key) {
    if (const settings_table::WorldKey* row = settings_table::findWorldKey(key))
        return worldShape(row->kind);
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos || dot == 0) return std::nullopt;
    const std::string field = key.substr(dot + 1);
    if (!isBlockField(field)) return std::nullopt;
    return blockShape(settings_table::blockKey(field.c_str()).kind);
}

// ---- Reading a log ----

SceneError lineError(const std::string& source, std::size_t line, const std::string& message) {
    return sceneError(source + ":" + std::to_string(line), message);
}

// One line's object, at `path` ("" for a line of a file: its keys are named alone); throws
// scene_json::ValueError naming the key at fault.
JournalEntry readEntry(const json& object, const std::string& path, std::uint64_t lastFrame) {
    using namespace scene_json;
    const std::string line = path.empty() ? "(line)" : path;
    const auto at = [&path](const char* key) { return keyPath(path, key); };
    requireObject(object, line);
    checkKeys(object, path,
              {"frame", "set", "value", "continues", "add", "remove", "undo", "redo"});
    if (!object.contains("frame")) throw ValueError{line, "missing \"frame\""};
    JournalEntry entry;
    entry.frame = static_cast<std::uint64_t>(number(object["frame"], at("frame"), limits::kFrames));
    if (entry.frame < lastFrame)
        throw ValueError{at("frame"), std::to_string(entry.frame) + " comes after frame " +
                                          std::to_string(lastFrame) +
                                          ": a log lists its edits in the order they apply"};
    int kinds = 0;
    for (const char* what : {"set", "add", "remove", "undo", "redo"})
        kinds += object.contains(what) ? 1 : 0;
    if (kinds != 1)
        throw ValueError{line, "must have one of \"set\", \"add\", \"remove\", \"undo\" or "
                               "\"redo\""};
    if (object.contains("value") && !object.contains("set"))
        throw ValueError{at("value"), "only a \"set\" has a value"};
    if (object.contains("continues") && !object.contains("set"))
        throw ValueError{at("continues"), "only a \"set\" continues the edit before it"};
    for (const char* what : {"undo", "redo"}) {
        if (!object.contains(what)) continue;
        if (object[what] != true) throw ValueError{at(what), "must be true"};
        entry.what = what[0] == 'u' ? JournalEntry::What::Undo : JournalEntry::What::Redo;
        return entry;
    }
    if (object.contains("add")) {
        requireObject(object["add"], at("add"));
        entry.edit = Edit::add(object["add"]);
        return entry;
    }
    if (object.contains("remove")) {
        const std::string block = string(object["remove"], at("remove"));
        if (block.empty()) throw ValueError{at("remove"), "must name a block"};
        entry.edit = Edit::remove(parseRef(block));
        return entry;
    }
    const std::string key = string(object["set"], at("set"));
    if (!object.contains("value")) throw ValueError{keyPath(path, key), "missing \"value\""};
    if (object.contains("continues")) {
        if (!object["continues"].is_boolean())
            throw ValueError{at("continues"), "must be true or false"};
        entry.continues = object["continues"].get<bool>();
    }
    EditError error;
    std::optional<Edit> edit = setEdit(key, object["value"], error);
    if (!edit) throw ValueError{path.empty() ? error.key : path + "." + error.key, error.message};
    entry.edit = std::move(*edit);
    return entry;
}

} // namespace

std::optional<Edit> setEdit(const std::string& key, nlohmann::json value, EditError& error) {
    if (settings_table::findWorldKey(key)) return Edit::setWorld(key, std::move(value));
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos || dot == 0) {
        error = {printable(key), "no such world key (" + worldKeyNames() +
                                     "), nor BLOCK.FIELD (a block's name or place, a dot, a "
                                     "field: m2.mass, blocks[1].mass)"};
        return std::nullopt;
    }
    const std::string field = key.substr(dot + 1);
    if (!isBlockField(field)) {
        error = {printable(key),
                 "no block field \"" + printable(field) + "\" (" + blockFieldNames() + ")"};
        return std::nullopt;
    }
    return Edit::setBlock(parseRef(key.substr(0, dot)), field, std::move(value));
}

std::optional<Edit> parseSet(const std::string& text, EditError& error) {
    for (std::size_t eq = text.find('='); eq != std::string::npos; eq = text.find('=', eq + 1)) {
        const std::string key = text.substr(0, eq);
        const std::optional<Shape> shape = shapeOfKey(key);
        if (!shape) continue;
        return setEdit(key, textValue(text.substr(eq + 1), *shape), error);
    }
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) {
        error = {"", "must be KEY=VALUE, e.g. bounciness=0.5 or m2.mass=4"};
        return std::nullopt;
    }
    setEdit(text.substr(0, eq), nullptr, error); // says why the key is none
    return std::nullopt;
}

EditLogResult parseEditLog(const std::string& text, const std::string& source) {
    EditLogResult result;
    EditLog log;
    log.source = source;
    std::size_t lineNumber = 0;
    std::uint64_t lastFrame = 0;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (log.lines.size() >= kMaxLogLines) {
            result.error = lineError(source, lineNumber,
                                     "more than " + std::to_string(kMaxLogLines) + " edits");
            return result;
        }
        json object;
        if (std::optional<SceneError> e = parseJsonText(line, "", object)) {
            // The place is "" + ":1:COLUMN" within the line: the file's line instead.
            const std::string column = e->where.rfind(":1:", 0) == 0 ? e->where.substr(2) : "";
            result.error =
                sceneError(source + ":" + std::to_string(lineNumber) + column, e->message);
            return result;
        }
        try {
            JournalEntry entry = readEntry(object, "", lastFrame);
            lastFrame = entry.frame;
            log.lines.push_back({std::move(entry), source + ":" + std::to_string(lineNumber)});
        } catch (const scene_json::ValueError& e) {
            result.error = lineError(source, lineNumber, e.path + ": " + e.message);
            return result;
        }
    }
    result.log = std::move(log);
    return result;
}

EditLogResult readEditLog(const std::string& path) {
    std::string text;
    if (std::optional<SceneError> e = readJsonFile(path, text)) {
        EditLogResult result;
        result.error = *e;
        return result;
    }
    return parseEditLog(text, path);
}

EditLog editLogOf(const nlohmann::json& lines, const std::string& path) {
    if (!lines.is_array()) throw scene_json::ValueError{path, "must be an array of edits"};
    if (lines.size() > kMaxLogLines)
        throw scene_json::ValueError{path, "more than " + std::to_string(kMaxLogLines) + " edits"};
    EditLog log;
    log.source = path;
    std::uint64_t lastFrame = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string at = scene_json::indexPath(path, i);
        JournalEntry entry = readEntry(lines[i], at, lastFrame);
        lastFrame = entry.frame;
        log.lines.push_back({std::move(entry), at});
    }
    return log;
}

SceneError logLineError(const LogLine& line, const EditError& error) {
    return sceneError(line.place, error.text());
}

std::string logLineText(const JournalEntry& entry) {
    // Written as the docs write it: {"frame": 30, "set": "bounciness", "value": 0.5}.
    std::string out = "{\"frame\": " + std::to_string(entry.frame);
    const auto field = [&out](const char* key, const json& value) {
        out += std::string(", \"") + key + "\": " + scene_json::dumpValue(value);
    };
    switch (entry.what) {
    case JournalEntry::What::Undo:
        field("undo", true);
        break;
    case JournalEntry::What::Redo:
        field("redo", true);
        break;
    case JournalEntry::What::Edit:
        switch (entry.edit.kind) {
        case Edit::Kind::SetWorld:
        case Edit::Kind::SetBlock:
            field("set", editKey(entry.edit));
            field("value", *entry.edit.value);
            if (entry.continues) field("continues", true);
            break;
        case Edit::Kind::Add:
            field("add", *entry.edit.value);
            break;
        case Edit::Kind::Remove:
            field("remove", refText(entry.edit.block));
            break;
        }
        break;
    }
    return out + "}";
}

std::string logText(const std::vector<JournalEntry>& journal) {
    std::string out;
    for (const JournalEntry& entry : journal) out += logLineText(entry) + "\n";
    return out;
}

const LogLine* LogPlayer::next(std::uint64_t frame) {
    if (at_ >= log_.lines.size() || log_.lines[at_].entry.frame > frame) return nullptr;
    return &log_.lines[at_++];
}
