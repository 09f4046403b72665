#include "page_world_controls.h"

#include "app.h"
#include "edit.h"
#include "panel_rows.h"
#include "printable.h"
#include "scene_json.h"
#include "settings_table.h"

#include <cctype>

namespace {

using json = nlohmann::json;
using settings_table::Kind;
using settings_table::WorldKey;

// The unit the page's control takes: a rate's row (dt) is typed in seconds, as a scene file has it.
std::string controlUnit(const WorldKey& row) {
    if (!row.shown.asRate) return settings_table::shownUnit(row);
    return row.range.unit;
}

// "Bounciness C", "Time step dt in s", "Drag k in kg/m³" (a pair's axis is added after the name).
std::string controlLabel(const WorldKey& row, const char* axis = nullptr) {
    std::string label = row.shown.asRate ? std::string("time step ") + row.key : row.shown.name;
    if (label.empty()) label = row.key;
    if (*row.shown.symbol) label += std::string(" ") + row.shown.symbol;
    if (axis) label += std::string(", ") + axis;
    const bool hasUnit =
        row.kind == Kind::Number || row.kind == Kind::Whole || row.kind == Kind::Pair;
    const std::string unit = hasUnit ? controlUnit(row) : ""; // a choice's range is empty
    if (!unit.empty()) label += " in " + unit;
    label[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(label[0])));
    return label;
}

// The field the panel's warning names: its label ("bounciness C", "gravity"), the key for a row
// the panel shows otherwise (dt, shown there as a frame rate).
std::string warningField(const WorldKey& row) {
    const PanelRow* panel = panelRowOf(row);
    return panel && *panel->label && !row.shown.asRate ? panel->label : row.key;
}

json names(const WorldKey& row) {
    json list = json::array();
    for (int i = 0; i < row.names.count; ++i) list.push_back(row.names.name(i));
    return list;
}

} // namespace

settings_table::FlagProblem readWorldValue(const WorldKey& row, const std::string& text,
                                           WorldSettings& s) {
    if (row.kind != Kind::NameSet) return settings_table::readFlag(row, text, s);
    WorldSettings read = s;
    read.*row.bits = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(',', start);
        if (end == std::string::npos) end = text.size();
        const settings_table::FlagProblem p =
            settings_table::readFlag(row, text.substr(start, end - start), read);
        if (!p.expected.empty()) return p;
        start = end + 1;
    }
    s.*row.bits = read.*row.bits;
    return {};
}

bool acceptTypedNumber(App& app, const char* field, const std::string& text, double current,
                       const limits::Range& range, double& out, std::string& error) {
    double typed = 0.0;
    if (!limits::parseNumber(text, typed)) {
        error = std::string(field) + ": not a number";
        app.ui.typedWarning.note(field, TypedValue{false, current, error});
        return false;
    }
    const TypedValue check = checkTypedValue(field, typed, current, range);
    if (!app.ui.typedWarning.note(field, check)) {
        error = check.message;
        return false;
    }
    out = check.value;
    return true;
}

json worldControlsJson(const WorldSettings& s) {
    json rows = json::array();
    for (const WorldKey* row : panelOrder()) {
        json c = {{"key", row->key}, {"label", controlLabel(*row)}};
        switch (row->kind) {
        case Kind::Number:
        case Kind::Whole:
            c["kind"] = row->kind == Kind::Number ? "number" : "whole";
            c["value"] = row->kind == Kind::Number ? json(s.*row->number) : json(s.*row->whole);
            c["min"] = row->range.min;
            c["max"] = row->range.max;
            break;
        case Kind::Pair:
            c["kind"] = "pair";
            c["value"] = json::array({(s.*row->pair).x, (s.*row->pair).y});
            c["labels"] = json::array({controlLabel(*row, "x"), controlLabel(*row, "y")});
            c["min"] = row->range.min;
            c["max"] = row->range.max;
            break;
        case Kind::Choice:
            c["kind"] = "choice";
            c["value"] = row->names.name(row->getChoice(s));
            c["names"] = names(*row);
            break;
        case Kind::NameSet: {
            c["kind"] = "set";
            json set = json::array();
            for (int i = 0; i < row->names.count; ++i)
                if ((s.*row->bits >> i) & 1u) set.push_back(row->names.name(i));
            c["value"] = set;
            c["names"] = names(*row);
            break;
        }
        case Kind::Flag:
            c["kind"] = "flag";
            c["value"] = s.*row->flag;
            break;
        }
        rows.push_back(c);
    }
    return rows;
}

// The value is read into a copy of the world's settings; a change goes through the one door
// (SimulationSession::apply) as the key's value in a scene file's words, so it is undone, logged
// and kept on the timeline as the panel's change is.
bool applyWorldControl(App& app, const std::string& control, const std::string& value,
                       std::string& error) {
    const WorldSettings& current = app.sim.world().settings;
    WorldSettings s = current;
    for (const WorldKey* row : panelOrder()) {
        const std::string key = row->key;
        int axis = -1;
        if (row->kind == Kind::Pair && control == key + "-x") axis = 0;
        if (row->kind == Kind::Pair && control == key + "-y") axis = 1;
        if (control != key && axis < 0) continue;
        const std::string field = warningField(*row);
        bool taken = false;
        switch (row->kind) {
        case Kind::Number:
            taken = acceptTypedNumber(app, field.c_str(), value, s.*row->number, row->range,
                                      s.*row->number, error);
            break;
        case Kind::Whole: {
            double v = s.*row->whole;
            taken = acceptTypedNumber(app, field.c_str(), value, v, row->range, v, error);
            if (taken) s.*row->whole = static_cast<int>(v);
            break;
        }
        case Kind::Pair:
            if (axis < 0) continue; // the pair's controls are its axes
            taken = acceptTypedNumber(app, field.c_str(), value,
                                      axis ? (s.*row->pair).y : (s.*row->pair).x, row->range,
                                      axis ? (s.*row->pair).y : (s.*row->pair).x, error);
            break;
        case Kind::Choice:
        case Kind::Flag:
        case Kind::NameSet: {
            const settings_table::FlagProblem p = readWorldValue(*row, value, s);
            if (!p.expected.empty())
                error = key + ": '" + printable(p.text, 40) + "' " + p.expected;
            taken = p.expected.empty();
            break;
        }
        }
        if (taken && !settings_table::same(*row, s, current)) {
            const EditError refused = app.sim.apply(Edit::setWorld(key, settingJson(*row, s)));
            if (!refused.empty()) error = refused.text();
        }
        return true;
    }
    return false;
}
