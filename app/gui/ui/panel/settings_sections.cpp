// The controls panel's sections that edit the world and its blocks (settings_sections.h).
#include "settings_sections.h"

#include "app.h"
#include "input_map.h"
#include "settings_table.h"
#include "typed_field.h"
#include "ui_style.h"

#include <imgui.h>

#include <cstddef>
#include <string>

namespace {

// ---- The world's settings: one widget per row of the table (settings_table.h), by its kind ----

using settings_table::WorldKey;

void choiceCombo(const WorldKey& row, WorldSettings& s, bool touch) {
    const int current = row.getChoice(s);
    const std::string label = keyedLabel(row.panel.label, actionOfControl(row.key), touch);
    if (ImGui::BeginCombo(label.c_str(), row.names.name(current))) {
        uiBeginRows();
        for (int i = 0; i < row.names.count; ++i) {
            if (ImGui::Selectable(row.names.name(i), i == current) && i != current)
                row.setChoice(s, i);
        }
        uiEndRows();
        ImGui::EndCombo();
    }
}

// A slider; a typed value (Ctrl+click) within the row's range is taken. A rate (dt) is shown
// and typed as 1/value.
void numberSlider(App& app, const WorldKey& row, WorldSettings& s) {
    double& value = s.*row.number;
    const double shown = row.shown.asRate ? 1.0 / value : value;
    float typed = static_cast<float>(shown);
    const float width = ImGui::CalcItemWidth();
    if (ImGui::SliderFloat(row.panel.label, &typed, row.panel.min, row.panel.max, row.panel.format,
                           row.panel.logarithmic ? ImGuiSliderFlags_Logarithmic : 0)) {
        double taken = shown;
        if (acceptTyped(app, row.panel.label, typed, row.panel.format, shown,
                        row.shown.asRate ? row.shown.rateRange : row.range, taken))
            value = row.shown.asRate ? 1.0 / taken : taken;
    }
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    if (&value == &s.bounciness) app.ui.bouncinessSlider = {a.x, a.y, b.x - a.x, b.y - a.y};
    // --verbose: where each slider is, once (the window test drags "bounciness").
    if (app.log.verbose && !app.log.layoutLogged) {
        std::printf("widget %s %d %d %d %d\n", row.key, static_cast<int>(a.x),
                    static_cast<int>(a.y), static_cast<int>(width), static_cast<int>(b.y - a.y));
    }
}

void wholeSlider(App& app, const WorldKey& row, WorldSettings& s) {
    int typed = s.*row.whole;
    if (ImGui::SliderInt(row.panel.label, &typed, static_cast<int>(row.panel.min),
                         static_cast<int>(row.panel.max), row.panel.format)) {
        double k = s.*row.whole;
        if (acceptTyped(app, row.panel.label, typed, row.panel.format, k, row.range, k))
            s.*row.whole = static_cast<int>(k);
    }
}

// Two sliders (x, y) with no label, then "0" and the preset (the default) and the symbol.
void pairSlider(App& app, const WorldKey& row, WorldSettings& s) {
    Vec2& value = s.*row.pair;
    float typed[2] = {static_cast<float>(value.x), static_cast<float>(value.y)};
    if (ImGui::SliderFloat2(("##" + std::string(row.key)).c_str(), typed, row.panel.min,
                            row.panel.max, row.panel.format)) {
        // Ctrl+click types a value beyond the slider: any within the limits is taken.
        acceptTyped2(app, row.panel.label, typed, row.panel.format, value, row.range, value);
    }
    tooltip(row.shown.tooltip);
    ImGui::SameLine();
    if (uiSmallButton("0")) value = Vec2{};
    if (ImGui::IsItemActivated()) app.ui.typedWarning.note(row.panel.label, TypedValue{});
    tooltip(("No " + std::string(row.shown.name)).c_str());
    ImGui::SameLine();
    if (uiSmallButton(row.panel.presetLabel)) value = defaultWorldSettings().*row.pair;
    if (ImGui::IsItemActivated()) app.ui.typedWarning.note(row.panel.label, TypedValue{});
    tooltip(row.panel.presetTooltip);
    ImGui::SameLine();
    ImGui::TextUnformatted(row.shown.symbol);
}

void nameChecks(const WorldKey& row, WorldSettings& s) {
    ImGui::TextColored(uiDimColor(), "%s", row.panel.label);
    for (int i = 0; i < row.names.count; ++i) {
        const auto bit = static_cast<std::uint8_t>(1u << i);
        bool on = (s.*row.bits & bit) != 0;
        if (ImGui::Checkbox(row.names.name(i), &on))
            s.*row.bits = static_cast<std::uint8_t>(on ? s.*row.bits | bit : s.*row.bits & ~bit);
        if (row.names.note) tooltip((std::string("Slide: \"") + row.names.note(i) + "\"").c_str());
    }
}

void settingWidget(App& app, const WorldKey& row) {
    WorldSettings& s = app.sim.world().settings;
    using settings_table::Kind;
    switch (row.kind) {
    case Kind::Choice:
        choiceCombo(row, s, app.ui.touchUi);
        break;
    case Kind::Number:
        numberSlider(app, row, s);
        break;
    case Kind::Whole:
        wholeSlider(app, row, s);
        break;
    case Kind::Pair:
        pairSlider(app, row, s);
        break;
    case Kind::NameSet:
        nameChecks(row, s);
        break;
    case Kind::Flag:
        ImGui::Checkbox(row.panel.label, &(s.*row.flag));
        break;
    }
    if (row.kind != Kind::Pair && *row.shown.tooltip) tooltip(row.shown.tooltip);
    typedWarning(app, row.panel.label);
}

// The rows of one section of the panel, in its order.
void settingWidgets(App& app, settings_table::Section section) {
    for (const WorldKey* row : settings_table::shownOrder())
        if (row->panel.section == section) settingWidget(app, *row);
}

// The selected block's own constant force [fx, fy] (N): a thruster that is always on.
void blockForceField(App& app, Block& b) {
    const settings_table::BlockKey& row = settings_table::blockKey("force");
    float f[2] = {static_cast<float>(b.force.x), static_cast<float>(b.force.y)};
    Vec2 force = b.force;
    if (ImGui::DragFloat2(row.label, f, 0.05f, -1000.0f, 1000.0f, row.sliderFormat) &&
        acceptTyped2(app, row.label, f, row.sliderFormat, b.force, row.range, force) &&
        acceptAcceleration(app, row.label, force, b.mass)) {
        b.force = force;
        app.sim.noteEdit(true);
    }
    tooltip(row.tooltip);
    typedWarning(app, row.label);
}

} // namespace

void simulationSection(App& app) {
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    settingWidgets(app, settings_table::Section::Simulation);
    if (app.log.verbose) app.log.layoutLogged = true;
    float scale = static_cast<float>(app.sim.timeScale);
    if (ImGui::SliderFloat("time scale", &scale, 0.05f, 4.0f, "%.2fx",
                           ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "time scale", scale, "%.2fx", app.sim.timeScale, limits::kTimeScale,
                    app.sim.timeScale);
    }
    typedWarning(app, "time scale");
}

void physicsSection(App& app) {
    // Opens for a scene that uses it (thruster, feather and stone, the mistakes), else closed.
    const std::string scene = app.sim.scenePath + "\n" + app.sim.scene.name;
    if (scene != app.ui.physicsFollowedScene) {
        ImGui::SetNextItemOpen(app.sim.usesPhysicsSection(), ImGuiCond_Always);
        app.ui.physicsFollowedScene = scene;
    }
    if (!ImGui::CollapsingHeader("Physics")) return;
    settingWidgets(app, settings_table::Section::Physics);
    ImGui::Separator();
    ImGui::Checkbox("Thrust (arrow keys)", &app.sim.thrust.on);
    tooltip("Hold the arrow keys to push the selected block with the thrust force (added to its "
            "own force while held). The arrows then do not step a lesson: PageDown / PageUp do "
            "(slide \"Spaceship thruster: big ship: slow acceleration; small ship: fast\")");
    float thrust = static_cast<float>(app.sim.thrust.force);
    if (ImGui::SliderFloat("thrust force", &thrust, 0.1f, 1000.0f, "%.3g N",
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
    Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
    ImGui::Text("%s", app.sim.blockDisplayName(i).c_str());
    int kind = static_cast<int>(b.kind);
    bool changed = ImGui::RadioButton("dynamic", &kind, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("static", &kind, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("kinematic", &kind, 2);
    if (changed) app.sim.setBlockKind(i, static_cast<BodyKind>(kind));
    if (b.isDynamic()) {
        const settings_table::BlockKey& massRow = settings_table::blockKey("mass");
        float mass = static_cast<float>(b.mass);
        double newMass = b.mass;
        if (ImGui::SliderFloat(massRow.label, &mass, 0.01f, 1000.0f, massRow.sliderFormat,
                               ImGuiSliderFlags_Logarithmic) &&
            acceptTyped(app, massRow.label, mass, massRow.sliderFormat, b.mass, massRow.range,
                        newMass) &&
            acceptAcceleration(app, massRow.label, b.force, newMass)) {
            b.mass = newMass;
            app.sim.noteEdit(true);
        }
        typedWarning(app, massRow.label);
        blockForceField(app, b);
    } else {
        ImGui::TextColored(uiDimColor(), "mass: infinite");
    }
    const settings_table::BlockKey& sizeRow = settings_table::blockKey("size");
    float size[2] = {static_cast<float>(b.size.x), static_cast<float>(b.size.y)};
    if (ImGui::DragFloat2(sizeRow.label, size, 0.02f, 0.05f, 50.0f, sizeRow.sliderFormat)) {
        Vec2 wanted = b.size;
        if (acceptTyped2(app, sizeRow.label, size, sizeRow.sliderFormat, b.size, sizeRow.range,
                         wanted) &&
            !app.sim.setBlockSize(i, wanted)) {
            app.ui.typedWarning.note(
                sizeRow.label,
                {false, 0.0, "size: that size would overlap another block or a wall"});
        }
    }
    typedWarning(app, sizeRow.label);
    if (b.kind != BodyKind::Static) {
        const settings_table::BlockKey& velocityRow = settings_table::blockKey("velocity");
        float v[2] = {static_cast<float>(b.velocity.x), static_cast<float>(b.velocity.y)};
        if (ImGui::DragFloat2(velocityRow.label, v, 0.05f, -1000.0f, 1000.0f,
                              velocityRow.sliderFormat) &&
            acceptTyped2(app, velocityRow.label, v, velocityRow.sliderFormat, b.velocity,
                         velocityRow.range, b.velocity)) {
            app.sim.noteEdit(true);
        }
        typedWarning(app, velocityRow.label);
    }
    ImGui::TextColored(uiDimColor(), "position (%.2f, %.2f) m", b.position.x, b.position.y);
    if (ImGui::Button("Delete block")) deleteSelected(app);
}
