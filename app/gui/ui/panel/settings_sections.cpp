// The controls panel's sections that edit the world and its blocks (settings_sections.h).
#include "settings_sections.h"

#include "app.h"
#include "input_map.h"
#include "panel_rows.h"
#include "scene_json.h"
#include "settings_table.h"
#include "slider.h"
#include "typed_field.h"
#include "ui_style.h"

#include <imgui.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>

namespace {

// ---- The world's settings: one widget per row of the table (settings_table.h), by its kind ----
// A widget never writes the world: it makes an edit of the row (the one door, docs/edits.md).

using settings_table::WorldKey;

// After a widget is drawn: pressed, it begins a gesture (a slider dragged is one undo step).
bool widgetChanged(App& app, bool changed) {
    if (ImGui::IsItemActivated()) app.sim.beginGesture();
    return changed;
}

// The row's value in `next` as an edit; while the widget is held, part of its gesture. A
// refusal shows under the field.
void applyRow(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& next) {
    const EditError error =
        app.sim.apply(Edit::setWorld(row.key, settingJson(row, next)), ImGui::IsItemActive());
    if (!error.empty()) app.ui.typedWarning.note(panel.label, TypedValue{false, 0.0, error.text()});
}

void choiceCombo(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& s) {
    const int current = row.getChoice(s);
    const std::string label = keyedLabel(panel.label, actionOfControl(row.key), app.ui.touchUi);
    if (ImGui::BeginCombo(label.c_str(), row.names.name(current))) {
        uiBeginRows();
        for (int i = 0; i < row.names.count; ++i) {
            if (ImGui::Selectable(row.names.name(i), i == current) && i != current) {
                WorldSettings next = s;
                row.setChoice(next, i);
                app.sim.beginGesture();
                applyRow(app, row, panel, next);
            }
        }
        uiEndRows();
        ImGui::EndCombo();
    }
}

// A slider; a typed value (Ctrl+click) within the row's range is taken. A rate (dt) is shown
// and typed as 1/value.
void numberSlider(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& s) {
    const double value = s.*row.number;
    const double shown = row.shown.asRate ? 1.0 / value : value;
    float typed = static_cast<float>(shown);
    const float width = ImGui::CalcItemWidth();
    if (widgetChanged(app, uiSliderFloat(panel.label, &typed, panel.min, panel.max, panel.format,
                                         panel.logarithmic ? ImGuiSliderFlags_Logarithmic : 0))) {
        double taken = shown;
        if (acceptTyped(app, panel.label, typed, panel.format, shown,
                        row.shown.asRate ? row.shown.rateRange : row.range, taken)) {
            WorldSettings next = s;
            next.*row.number = row.shown.asRate ? 1.0 / taken : taken;
            applyRow(app, row, panel, next);
        }
    }
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    if (std::string(row.key) == "bounciness")
        app.ui.bouncinessSlider = {a.x, a.y, b.x - a.x, b.y - a.y};
    // --verbose: where each slider is, once (the window test drags "bounciness").
    if (app.log.verbose && !app.log.layoutLogged) {
        std::printf("widget %s %d %d %d %d\n", row.key, static_cast<int>(a.x),
                    static_cast<int>(a.y), static_cast<int>(width), static_cast<int>(b.y - a.y));
    }
}

void wholeSlider(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& s) {
    int typed = s.*row.whole;
    if (widgetChanged(app, uiSliderInt(panel.label, &typed, static_cast<int>(panel.min),
                                       static_cast<int>(panel.max), panel.format))) {
        double k = s.*row.whole;
        if (acceptTyped(app, panel.label, typed, panel.format, k, row.range, k)) {
            WorldSettings next = s;
            next.*row.whole = static_cast<int>(k);
            applyRow(app, row, panel, next);
        }
    }
}

// Two sliders (x, y) with no label, then "0" and the preset (the default) and the symbol.
void pairSlider(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& s) {
    const Vec2 value = s.*row.pair;
    WorldSettings next = s;
    float typed[2] = {static_cast<float>(value.x), static_cast<float>(value.y)};
    // Ctrl+click types a value beyond the slider: any within the limits is taken.
    if (widgetChanged(app, uiSliderFloat2(("##" + std::string(row.key)).c_str(), typed, panel.min,
                                          panel.max, panel.format)) &&
        acceptTyped2(app, panel.label, typed, panel.format, value, row.range, next.*row.pair))
        applyRow(app, row, panel, next);
    tooltip(panel.tooltip);
    const std::pair<const char*, Vec2> presets[] = {
        {"0", Vec2{}}, {panel.presetLabel, defaultWorldSettings().*row.pair}};
    for (const auto& [label, preset] : presets) {
        ImGui::SameLine();
        if (uiSmallButton(label)) {
            next.*row.pair = preset;
            app.sim.beginGesture();
            applyRow(app, row, panel, next);
        }
        if (ImGui::IsItemActivated()) app.ui.typedWarning.note(panel.label, TypedValue{});
        tooltip(preset == Vec2{} ? ("No " + std::string(row.shown.name)).c_str()
                                 : panel.presetTooltip);
    }
    ImGui::SameLine();
    ImGui::TextUnformatted(row.shown.symbol);
}

void nameChecks(App& app, const WorldKey& row, const PanelRow& panel, const WorldSettings& s) {
    ImGui::TextColored(uiDimColor(), "%s", panel.label);
    for (int i = 0; i < row.names.count; ++i) {
        const auto bit = static_cast<std::uint8_t>(1u << i);
        bool on = (s.*row.bits & bit) != 0;
        if (widgetChanged(app, ImGui::Checkbox(row.names.name(i), &on))) {
            WorldSettings next = s;
            next.*row.bits = static_cast<std::uint8_t>(on ? s.*row.bits | bit : s.*row.bits & ~bit);
            applyRow(app, row, panel, next);
        }
        if (row.names.note) tooltip((std::string("Slide: \"") + row.names.note(i) + "\"").c_str());
    }
}

void settingWidget(App& app, const WorldKey& row, const PanelRow& panel) {
    const WorldSettings& s = app.sim.world().settings;
    using settings_table::Kind;
    switch (row.kind) {
    case Kind::Choice:
        choiceCombo(app, row, panel, s);
        break;
    case Kind::Number:
        numberSlider(app, row, panel, s);
        break;
    case Kind::Whole:
        wholeSlider(app, row, panel, s);
        break;
    case Kind::Pair:
        pairSlider(app, row, panel, s);
        break;
    case Kind::NameSet:
        nameChecks(app, row, panel, s);
        break;
    case Kind::Flag: {
        bool on = s.*row.flag;
        if (widgetChanged(app, ImGui::Checkbox(panel.label, &on))) {
            WorldSettings next = s;
            next.*row.flag = on;
            applyRow(app, row, panel, next);
        }
        break;
    }
    }
    if (row.kind != Kind::Pair && *panel.tooltip) tooltip(panel.tooltip);
    typedWarning(app, panel.label);
}

// The rows of one section of the panel, in its order.
void settingWidgets(App& app, PanelSection section) {
    for (const WorldKey* row : panelOrder())
        if (const PanelRow* panel = panelRowOf(*row); panel && panel->section == section)
            settingWidget(app, *row, *panel);
}

// ---- The selected block: each field an edit of it ----

// Block `i`'s field `key` set to `value` (a scene file's form), part of the widget's gesture
// while it is held; a refusal shows under the field (`label`).
void applyField(App& app, int i, const char* key, const nlohmann::json& value, const char* label) {
    const EditError error =
        app.sim.apply(Edit::setBlock({i, ""}, key, value), ImGui::IsItemActive());
    if (!error.empty()) app.ui.typedWarning.note(label, TypedValue{false, 0.0, error.text()});
}

// The selected block's own constant force [fx, fy] (N): a thruster that is always on.
void blockForceField(App& app, int i, const Block& b) {
    const settings_table::BlockKey& row = settings_table::blockKey("force");
    const BlockPanelRow& panel = blockPanelRow("force");
    float f[2] = {static_cast<float>(b.force.x), static_cast<float>(b.force.y)};
    Vec2 force = b.force;
    if (widgetChanged(app,
                      ImGui::DragFloat2(panel.label, f, 0.05f, -1000.0f, 1000.0f, panel.format)) &&
        acceptTyped2(app, panel.label, f, panel.format, b.force, row.range, force) &&
        acceptAcceleration(app, panel.label, force, b.mass))
        applyField(app, i, row.key, {force.x, force.y}, panel.label);
    tooltip(panel.tooltip);
    typedWarning(app, panel.label);
}

} // namespace

void simulationSection(App& app) {
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    settingWidgets(app, PanelSection::Simulation);
    if (app.log.verbose) app.log.layoutLogged = true;
    float scale = static_cast<float>(app.sim.timeScale);
    if (uiSliderFloat("time scale", &scale, 0.05f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "time scale", scale, "%.2fx", app.sim.timeScale, limits::kTimeScale,
                    app.sim.timeScale);
    }
    typedWarning(app, "time scale");
}

void physicsSection(App& app) {
    // Opens for a scene that uses it (thruster, feather and stone, the mistakes), else closed.
    const std::string scene = app.sim.scenePath + "\n" + app.sim.scene.name;
    if (scene != app.ui.physicsFollowedScene) {
        ImGui::SetNextItemOpen(usesPhysicsSection(app.sim.scene, app.sim.thrust.on),
                               ImGuiCond_Always);
        app.ui.physicsFollowedScene = scene;
    }
    if (!ImGui::CollapsingHeader("Physics")) return;
    settingWidgets(app, PanelSection::Physics);
    ImGui::Separator();
    ImGui::Checkbox("Thrust (arrow keys)", &app.sim.thrust.on);
    tooltip("Hold the arrow keys to push the selected block with the thrust force (added to its "
            "own force while held). The arrows then do not step a lesson: PageDown / PageUp do "
            "(slide \"Spaceship thruster: big ship: slow acceleration; small ship: fast\")");
    float thrust = static_cast<float>(app.sim.thrust.force);
    if (uiSliderFloat("thrust force", &thrust, 0.1f, 1000.0f, "%.3g N",
                      ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "thrust force", thrust, "%.3g N", app.sim.thrust.force, limits::kThrust,
                    app.sim.thrust.force);
    }
    tooltip("F in N: the same force gives a heavy block a small acceleration a = F/m, a light one "
            "a large one (Ctrl+click to type)");
    typedWarning(app, "thrust force");
    if (app.sim.thrust.on &&
        !(app.sim.selected >= 0 &&
          app.sim.selected < static_cast<int>(app.sim.world().blocks.size()) &&
          app.sim.world().blocks[static_cast<std::size_t>(app.sim.selected)].isDynamic())) {
        ImGui::TextColored(uiDimColor(), "Select a moving block to push it.");
    }
}

void selectedSection(App& app) {
    // Opens when a block gets selected, closes when the selection goes; the user may still fold it.
    if (app.sim.selected != app.ui.panelFollowedSelection) {
        ImGui::SetNextItemOpen(app.sim.selected >= 0, ImGuiCond_Always);
        app.ui.panelFollowedSelection = app.sim.selected;
    }
    if (!ImGui::CollapsingHeader("Selected block")) return;
    const int i = app.sim.selected;
    if (i < 0 || i >= static_cast<int>(app.sim.world().blocks.size())) {
        ImGui::TextColored(uiDimColor(), "Click a block to select it.");
        ImGui::TextColored(uiDimColor(), "Double-click empty space to add one.");
        return;
    }
    const Block b = app.sim.world().blocks[static_cast<std::size_t>(i)];
    ImGui::Text("%s", app.sim.blockDisplayName(i).c_str());
    int kind = static_cast<int>(b.kind);
    bool changed = ImGui::RadioButton("dynamic", &kind, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("static", &kind, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("kinematic", &kind, 2);
    if (changed) {
        app.sim.beginGesture();
        app.sim.setBlockKind(i, static_cast<BodyKind>(kind));
    }
    if (b.isDynamic()) {
        const settings_table::BlockKey& massRow = settings_table::blockKey("mass");
        const BlockPanelRow& massPanel = blockPanelRow("mass");
        float mass = static_cast<float>(b.mass);
        double newMass = b.mass;
        if (widgetChanged(app, uiSliderFloat(massPanel.label, &mass, 0.01f, 1000.0f,
                                             massPanel.format, ImGuiSliderFlags_Logarithmic)) &&
            acceptTyped(app, massPanel.label, mass, massPanel.format, b.mass, massRow.range,
                        newMass) &&
            acceptAcceleration(app, massPanel.label, b.force, newMass))
            applyField(app, i, massRow.key, newMass, massPanel.label);
        typedWarning(app, massPanel.label);
        blockForceField(app, i, b);
    } else {
        ImGui::TextColored(uiDimColor(), "mass: infinite");
    }
    const settings_table::BlockKey& sizeRow = settings_table::blockKey("size");
    const BlockPanelRow& sizePanel = blockPanelRow("size");
    float size[2] = {static_cast<float>(b.size.x), static_cast<float>(b.size.y)};
    Vec2 wanted = b.size;
    if (widgetChanged(
            app, ImGui::DragFloat2(sizePanel.label, size, 0.02f, 0.05f, 50.0f, sizePanel.format)) &&
        acceptTyped2(app, sizePanel.label, size, sizePanel.format, b.size, sizeRow.range, wanted))
        applyField(app, i, sizeRow.key, {wanted.x, wanted.y}, sizePanel.label);
    typedWarning(app, sizePanel.label);
    if (b.kind != BodyKind::Static) {
        const settings_table::BlockKey& velocityRow = settings_table::blockKey("velocity");
        const BlockPanelRow& velocityPanel = blockPanelRow("velocity");
        float v[2] = {static_cast<float>(b.velocity.x), static_cast<float>(b.velocity.y)};
        Vec2 velocity = b.velocity;
        if (widgetChanged(app, ImGui::DragFloat2(velocityPanel.label, v, 0.05f, -1000.0f, 1000.0f,
                                                 velocityPanel.format)) &&
            acceptTyped2(app, velocityPanel.label, v, velocityPanel.format, b.velocity,
                         velocityRow.range, velocity))
            applyField(app, i, velocityRow.key, {velocity.x, velocity.y}, velocityPanel.label);
        typedWarning(app, velocityPanel.label);
    }
    ImGui::TextColored(uiDimColor(), "position (%.2f, %.2f) m", b.position.x, b.position.y);
    if (ImGui::Button("Delete block")) deleteSelected(app);
}
