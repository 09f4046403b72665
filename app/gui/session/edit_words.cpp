#include "edit_words.h"

#include "panel_rows.h"
#include "scene.h"
#include "scene_json.h"
#include "settings_table.h"
#include "text_format.h"

#include <cstdio>
#include <cstring>

namespace {

using json = nlohmann::json;

// `value` by a printf format with one number in it ("%.2f", "%.0f Hz").
std::string printed(const char* format, double value) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, value);
    return buf;
}

// A pair by a format of one number and a unit ("%.2f m/s": "(3.00, 0.00) m/s") or of two
// ("(%.2f, %.2f) m").
std::string printedPair(const std::string& format, Vec2 v) {
    const std::size_t first = format.find('%');
    if (format.find('%', first + 1) != std::string::npos) {
        char buf[160];
        std::snprintf(buf, sizeof buf, format.c_str(), v.x, v.y);
        return buf;
    }
    const std::size_t end = format.find_first_of("fgeGEd", first);
    const std::string number = format.substr(0, end + 1), unit = format.substr(end + 1);
    return "(" + printed(number.c_str(), v.x) + ", " + printed(number.c_str(), v.y) + ")" + unit;
}

// A world setting with the panel's digits: "0.90", "60 Hz", "(0.00, -9.81) m/s²", "turn-based".
std::string settingText(const settings_table::WorldKey& row, const WorldSettings& s) {
    using settings_table::Kind;
    const PanelRow* panel = panelRowOf(row);
    const char* format = panel && *panel->format ? panel->format : "%.6g";
    switch (row.kind) {
    case Kind::Number: {
        const double v = s.*row.number;
        return printed(format, row.shown.asRate ? 1.0 / v : v);
    }
    case Kind::Pair:
        return printedPair(format, s.*row.pair) + " " + settings_table::shownUnit(row);
    case Kind::NameSet:
        return settings_table::isNone(row, s) ? "none" : settings_table::setNames(row, s, ", ");
    case Kind::Whole:
    case Kind::Choice:
    case Kind::Flag:
        break;
    }
    return settings_table::logValue(row, s);
}

// A block's field with the panel's digits: "4 kg", "(3.00, 0.00) m/s", "static".
std::string fieldText(const settings_table::BlockKey& row, const BlockDef& def) {
    const json block = blockJson(def);
    if (!block.contains(row.key)) return "none";
    const json& value = block[row.key];
    const char* format = "";
    for (const BlockPanelRow& p : blockPanelRows())
        if (std::strcmp(p.key, row.key) == 0) format = p.format;
    if (!*format || value.is_string()) return scene_json::dumpValue(value);
    if (value.is_number()) return printed(format, value.get<double>());
    return printedPair(format, {value[0].get<double>(), value[1].get<double>()});
}

} // namespace

std::string spokenBlockName(const std::vector<BlockLabel>& labels, int index) {
    const auto i = static_cast<std::size_t>(index);
    if (i >= labels.size() || labels[i].name.empty()) return refText(BlockRef{index, ""});
    const std::string base = baseBlockName(labels[i].name);
    for (std::size_t j = 0; j < labels.size(); ++j) {
        if (j != i && (labels[j].name == base || baseBlockName(labels[j].name) == base))
            return labels[i].name; // two blocks would be called that
    }
    return base;
}

std::string editLogLine(const Edit& logged, int index, const World& world,
                        const std::vector<BlockLabel>& labels) {
    switch (logged.kind) {
    case Edit::Kind::SetWorld:
        if (const settings_table::WorldKey* row = settings_table::findWorldKey(logged.key))
            return logged.key + ": " + settings_table::logValue(*row, world.settings);
        break;
    case Edit::Kind::SetBlock: // "m2 mass: 4" (the block "m2 = 2 kg")
        return spokenBlockName(labels, index) + " " + logged.key + ": " +
               scene_json::dumpValue(*logged.value);
    case Edit::Kind::Add:
        return "add: blocks[" + std::to_string(world.blocks.size() - 1) + "]";
    case Edit::Kind::Remove:
        return "remove: " + refText(logged.block);
    }
    return editKey(logged);
}

std::string editChangeText(const AppliedEdit& a, bool undone,
                           const std::vector<BlockLabel>& labels) {
    const std::string arrow = " -> ";
    switch (a.edit.kind) {
    case Edit::Kind::SetWorld: {
        const settings_table::WorldKey* row = settings_table::findWorldKey(a.edit.key);
        if (!row) break;
        const std::string before = settingText(*row, a.settingsBefore);
        const std::string after = settingText(*row, a.settingsAfter);
        return std::string(row->shown.name) + " " +
               (undone ? after + arrow + before : before + arrow + after);
    }
    case Edit::Kind::SetBlock: {
        const settings_table::BlockKey& row = settings_table::blockKey(a.edit.key.c_str());
        const std::string before = fieldText(row, a.before), after = fieldText(row, a.after);
        return spokenBlockName(labels, a.index) + " " + row.key + ": " +
               (undone ? after + arrow + before : before + arrow + after);
    }
    case Edit::Kind::Add: // "undo: add new 4"
        return "add " + (a.after.name.empty() ? refText({a.index, ""}) : a.after.name);
    case Edit::Kind::Remove:
        return "remove " + (a.before.name.empty() ? refText({a.index, ""}) : a.before.name);
    }
    return editKey(a.edit);
}

std::string editNowText(const AppliedEdit& a, bool undone, const std::vector<BlockLabel>& labels) {
    switch (a.edit.kind) {
    case Edit::Kind::SetWorld: {
        const settings_table::WorldKey* row = settings_table::findWorldKey(a.edit.key);
        if (!row) break;
        const std::string symbol = *row->shown.symbol ? std::string(" ") + row->shown.symbol : "";
        return std::string(row->shown.name) + symbol + " is now " +
               settingText(*row, undone ? a.settingsBefore : a.settingsAfter);
    }
    case Edit::Kind::SetBlock: {
        const settings_table::BlockKey& row = settings_table::blockKey(a.edit.key.c_str());
        return spokenBlockName(labels, a.index) + " " + row.key + " is now " +
               fieldText(row, undone ? a.before : a.after);
    }
    case Edit::Kind::Add:
    case Edit::Kind::Remove: {
        const BlockDef& def = a.edit.kind == Edit::Kind::Add ? a.after : a.before;
        const std::string name =
            def.name.empty() ? refText({a.index, ""}) : baseBlockName(def.name);
        return name + ((a.edit.kind == Edit::Kind::Add) != undone ? " added" : " removed");
    }
    }
    return editKey(a.edit);
}
