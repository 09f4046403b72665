// The controls panel: scene, run control, simulation settings, the selected block, statistics
// and view options, bound to App every frame (immediate mode: no state of its own).
#include "app_config.h"
#include "app_frame.h"
#include "overlay_window.h"
#include "save_naming.h"
#include "settings_table.h"
#include "ui_style.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

void tooltip(const char* text) {
    if (*text && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void statRow(const char* name, const char* fmt, double value) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    ImGui::Text(fmt, value);
}

// A value typed into `field` (Ctrl+click on a slider, or a drag field) checked against its limit
// (checkTypedValue, engine/input_limits.h): true and `out` set when it is good; otherwise the
// field keeps `current` and the panel warns under it until a good value comes.
bool acceptTyped(App& app, const char* field, double typed, double current,
                 const limits::Range& range, double& out) {
    const TypedValue check = checkTypedValue(field, typed, current, range);
    out = check.value;
    return app.ui.typedWarning.note(field, check);
}

// The same for a pair (x, y) from a 2-component field: each component that changed is checked,
// and both are taken or neither. The one that did not change keeps its double value.
bool acceptTyped2(App& app, const char* field, const float typed[2], Vec2 current,
                  const limits::Range& range, Vec2& out) {
    const double now[2] = {current.x, current.y};
    double wanted[2] = {current.x, current.y};
    TypedValue check;
    for (int k = 0; k < 2 && check.ok; ++k) {
        if (typed[k] == static_cast<float>(now[k])) continue;
        check = checkTypedValue(field, typed[k], now[k], range);
        wanted[k] = check.value;
    }
    if (check.ok) out = Vec2{wanted[0], wanted[1]};
    return app.ui.typedWarning.note(field, check);
}

// A block's force and mass together: F/m within what a scene file may hold (else the saved file
// would not load back); false and a warning under `field` when not.
bool acceptAcceleration(App& app, const char* field, Vec2 force, double mass) {
    const std::string problem = limits::accelerationViolation(length(force), mass);
    if (problem.empty()) return true;
    return app.ui.typedWarning.note(field,
                                    TypedValue{false, 0.0, std::string(field) + ": " + problem});
}

// The warning about `field`'s last typed value, under the field, in the warning colour.
void typedWarning(const App& app, const char* field) {
    const TypedWarning& w = app.ui.typedWarning;
    if (w.message.empty() || w.field != field) return;
    ImGui::PushStyleColor(ImGuiCol_Text, uiWarningColor());
    textWrappedAtSpaces(w.message);
    ImGui::PopStyleColor();
}

void scenePicker(App& app) {
    const char* preview = app.sim.scene.name.empty() ? "(no scene)" : app.sim.scene.name.c_str();
    const char* copyLink = "Copy link";
    const ImGuiStyle& style = ImGui::GetStyle();
    const float copyWidth = app.ui.inBrowser ? ImGui::CalcTextSize(copyLink).x +
                                                   2.0f * style.FramePadding.x + style.ItemSpacing.x
                                             : 0.0f;
    ImGui::SetNextItemWidth(-1.0f - copyWidth);
    // Taller than the default 8 rows: every shipped scene at once, in the lecture's order.
    if (ImGui::BeginCombo("##scene", preview, ImGuiComboFlags_HeightLargest)) {
        uiBeginRows();
        for (const SceneEntry& e : app.shipped.scenes) {
            const bool current = e.path == app.sim.scenePath;
            if (ImGui::Selectable(e.title.c_str(), current)) loadScene(app, e.path);
            if (current) ImGui::SetItemDefaultFocus();
        }
        if (app.shipped.scenes.empty()) ImGui::TextDisabled("no scenes found");
        if (!app.shipped.lessons.empty()) {
            ImGui::Separator();
            ImGui::TextDisabled("Lessons");
        }
        for (const SceneEntry& e : app.shipped.lessons) {
            const bool current = app.lesson.active() && app.lesson.lesson->path == e.path;
            const std::string label = "Lesson: " + e.title;
            if (ImGui::Selectable(label.c_str(), current)) openLesson(app, e.path);
        }
        uiEndRows();
        ImGui::EndCombo();
    }
    tooltip("The shipped scenes in the lecture's order (app/scenes/lecture_order.txt), and "
            "lessons (lessons/)");
    if (!app.ui.inBrowser) return;
    ImGui::SameLine();
    if (ImGui::Button(copyLink)) app.ui.copyLinkRequested = true;
    tooltip("A link for what is on screen: the scene (edited, it travels inside the link), the "
            "method, the overlays, the frame, the lesson's step. The address bar follows too.");
}

// The open lesson's steps: click one to go there.
void lessonSection(App& app) {
    LessonSession& s = app.lesson;
    if (!s.active()) return;
    if (!ImGui::CollapsingHeader("Lesson", ImGuiTreeNodeFlags_DefaultOpen)) return;
    textWrappedAtSpaces(s.lesson->name);
    const float w = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3;
    if (ImGui::Button("< Prev", ImVec2(w, 0))) applyAction(app, Action::LessonPrevious);
    tooltip("PageUp (or Left, with thrust off)");
    ImGui::SameLine();
    if (ImGui::Button(s.phase == LessonSession::Phase::Setup ? "Play >" : "Next >", ImVec2(w, 0)))
        applyAction(app, Action::LessonNext);
    tooltip("PageDown (or Right, with thrust off)");
    ImGui::SameLine();
    if (ImGui::Button("Restart (R)", ImVec2(w, 0))) applyAction(app, Action::Reset);
    tooltip("R: the step again from its setup, keeping the method and settings you changed; "
            "Shift+R: the step as written");
    const float rows = std::min<float>(8.0f, static_cast<float>(s.lesson->steps.size()));
    uiBeginRows();
    ImGui::BeginChild("##steps", ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing()));
    for (std::size_t i = 0; i < s.lesson->steps.size(); ++i) {
        const std::string label =
            std::to_string(i + 1) + ". " + s.lesson->steps[i].title + "##step" + std::to_string(i);
        const bool current = i == s.current;
        if (ImGui::Selectable(label.c_str(), current)) enterStep(app, i);
        if (current && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
    }
    ImGui::EndChild();
    uiEndRows();
    if (uiSmallButton("close lesson")) closeLesson(app);
    tooltip("Leave the lesson; the current scene stays");
}

void fileSection(App& app) {
    if (!ImGui::CollapsingHeader("Open and save")) return;
    if (app.ui.inBrowser) {
        if (ImGui::Button("Open a scene file...")) app.ui.filePickerRequested = true;
        tooltip("The browser's file dialog; or drop a .json file on the page (a .csv is a trace "
                "of your engine: the Compare section)");
        if (ImGui::Button("Save (download)")) applyAction(app, Action::Save);
        tooltip("Downloads the current state as a scene file (format v1) named after the scene; "
                "Ctrl+S");
        return;
    }
    ImGui::InputTextWithHint("##open", "path/to/scene.json", &app.ui.openPath);
    ImGui::SameLine();
    if (ImGui::Button("Open") && !app.ui.openPath.empty()) loadScene(app, app.ui.openPath);
    if (ImGui::Button("Save as... (Ctrl+S)")) applyAction(app, Action::Save);
    tooltip("Save the current state as a scene file (format v1): asks for a name");
}

// Check your own engine (docs/compare.md): a trace the student's engine printed, opened on the
// current scene and compared with it; the units it is in.
void compareSection(App& app) {
    if (!ImGui::CollapsingHeader("Compare your engine's trace")) return;
    StudentTrace& st = app.studentTrace;
    bool gxp = st.units.units == TraceUnits::Gxp;
    if (ImGui::RadioButton("SI (m, m/s, y up)", !gxp)) st.units.units = TraceUnits::Si;
    ImGui::SameLine();
    if (ImGui::RadioButton("gxp (pixels)", gxp)) {
        st.units.units = TraceUnits::Gxp;
        if (!(st.units.pxPerM > 0.0)) st.units.pxPerM = 50.0;
    }
    tooltip("gxp: pixels with y down, velocities in pixels per frame at the scene's frame rate");
    gxp = st.units.units == TraceUnits::Gxp;
    if (gxp) {
        double pxPerM = st.units.pxPerM;
        if (ImGui::InputDouble("px per m", &pxPerM, 0.0, 0.0, "%g") && pxPerM >= 1e-6 &&
            pxPerM <= 1e9)
            st.units.pxPerM = pxPerM;
        double origin[2] = {st.units.originPx.x, st.units.originPx.y};
        if (ImGui::InputScalarN("origin px", ImGuiDataType_Double, origin, 2, nullptr, nullptr,
                                "%g") &&
            std::abs(origin[0]) <= 1e9 && std::abs(origin[1]) <= 1e9)
            st.units.originPx = {origin[0], origin[1]};
        tooltip("The pixel of the world's top-left corner (your walls' margin)");
    }
    if (app.ui.inBrowser) {
        if (ImGui::Button("Open a trace...")) app.ui.filePickerRequested = true;
        tooltip("The browser's file dialog; or drop a .csv file on the page");
    } else {
        ImGui::InputTextWithHint("##trace", "path/to/my_trace.csv", &app.ui.tracePath);
        ImGui::SameLine();
        if (ImGui::Button("Open##trace") && !app.ui.tracePath.empty())
            openTrace(app, app.ui.tracePath);
        tooltip("A CSV with t, then NAME_x, NAME_y, NAME_vx, NAME_vy per block; or drop it on "
                "the window");
    }
    if (!st.open()) return;
    textWrappedAtSpaces(studentTraceSummary(st));
    if (uiSmallButton("first difference")) goToFirstDifference(app);
    ImGui::SameLine();
    if (uiSmallButton("compare again")) compareTraceAgain(app);
    tooltip("With the current settings (the method chosen above), from the start");
    ImGui::SameLine();
    if (uiSmallButton("close")) closeTrace(app);
}

void runSection(App& app) {
    if (!app.view.layout.sheet) { // the sheet has them in its bar
        const float w =
            (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3;
        if (ImGui::Button(app.sim.paused ? "Play  (P)" : "Pause (P)", ImVec2(w, 0))) {
            applyAction(app, Action::TogglePause);
        }
        ImGui::SameLine();
        if (ImGui::Button("Step (N)", ImVec2(w, 0))) applyAction(app, Action::StepOnce);
        ImGui::SameLine();
        if (ImGui::Button("Reset (R)", ImVec2(w, 0))) applyAction(app, Action::Reset);
        tooltip("Blocks and time back to the start; keeps the method, C, g, frame rate, substeps");
    }
    ImGui::Checkbox("Slow motion (Space)", &app.sim.slowMotion);
    tooltip("5 simulation frames per second, as in the lecture's demo");
    ImGui::SameLine();
    if (ImGui::Button("Reset to file")) applyAction(app, Action::ResetToFile);
    tooltip("Shift+R: everything as the scene file has it, settings included");
}

// ---- The world's settings: one widget per row of the table (settings_table.h), by its kind ----

using settings_table::WorldKey;

void choiceCombo(const WorldKey& row, WorldSettings& s) {
    const int current = row.getChoice(s);
    if (ImGui::BeginCombo(row.panel.label, row.names.name(current))) {
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
        if (acceptTyped(app, row.panel.label, typed, shown,
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
        if (acceptTyped(app, row.panel.label, typed, k, row.range, k))
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
        acceptTyped2(app, row.panel.label, typed, value, row.range, value);
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
        choiceCombo(row, s);
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

void simulationSection(App& app) {
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    settingWidgets(app, settings_table::Section::Simulation);
    if (app.log.verbose) app.log.layoutLogged = true;
    float scale = static_cast<float>(app.sim.timeScale);
    if (ImGui::SliderFloat("time scale", &scale, 0.05f, 4.0f, "%.2fx",
                           ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "time scale", scale, app.sim.timeScale, limits::kTimeScale,
                    app.sim.timeScale);
    }
    typedWarning(app, "time scale");
}

// Issue 16's settings (each a scene key, kept by R, restored by Shift+R, saved by Ctrl+S) and the
// keyboard thrust (the app's own: kept by both resets, set by a lesson step).
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
        acceptTyped(app, "thrust force", thrust, app.sim.thrust.force, limits::kThrust,
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

// The selected block's own constant force [fx, fy] (N): a thruster that is always on.
void blockForceField(App& app, Block& b) {
    const settings_table::BlockKey& row = settings_table::blockKey("force");
    float f[2] = {static_cast<float>(b.force.x), static_cast<float>(b.force.y)};
    Vec2 force = b.force;
    if (ImGui::DragFloat2(row.label, f, 0.05f, -1000.0f, 1000.0f, row.sliderFormat) &&
        acceptTyped2(app, row.label, f, b.force, row.range, force) &&
        acceptAcceleration(app, row.label, force, b.mass)) {
        b.force = force;
        app.sim.noteEdit(true);
    }
    tooltip(row.tooltip);
    typedWarning(app, row.label);
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
            acceptTyped(app, massRow.label, mass, b.mass, massRow.range, newMass) &&
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
        if (acceptTyped2(app, sizeRow.label, size, b.size, sizeRow.range, wanted) &&
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
            acceptTyped2(app, velocityRow.label, v, b.velocity, velocityRow.range, b.velocity)) {
            app.sim.noteEdit(true);
        }
        typedWarning(app, velocityRow.label);
    }
    ImGui::TextColored(uiDimColor(), "position (%.2f, %.2f) m", b.position.x, b.position.y);
    if (ImGui::Button("Delete block")) deleteSelected(app);
}

void statisticsSection(const Run& run, const UiState& ui) {
    if (!ImGui::CollapsingHeader("Statistics")) return;
    const StepStats& s = run.stats;
    if (!ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) return;
    statRow("collisions / frame", "%.0f", s.collisions);
    statRow("resting contacts / frame", "%.0f", s.contacts);
    statRow("events / frame", "%.0f", s.events);
    statRow("largest overlap", "%.4f m", s.maxPenetration);
    statRow("event-cap hits", "%.0f", static_cast<double>(run.totals.eventCapHits));
    statRow("step time", "%.3f ms", s.stepMs);
    statRow("collisions (total)", "%.0f", static_cast<double>(run.totals.collisions));
    statRow("resting contacts (total)", "%.0f", static_cast<double>(run.totals.contacts));
    statRow("momentum x", "%.3f kg·m/s", s.momentum.x);
    statRow("momentum y", "%.3f kg·m/s", s.momentum.y);
    statRow("kinetic energy", "%.3f J", s.kineticEnergy);
    statRow("total energy", "%.3f J", s.kineticEnergy + s.potentialEnergy);
    if (ui.frameMsSmoothed > 0.0) {
        statRow("display frame", "%.1f ms", ui.frameMsSmoothed);
        statRow("frames / second", "%.0f", 1000.0 / ui.frameMsSmoothed);
    }
    ImGui::EndTable();
}

void overlaysSection(Overlays& o) {
    if (!ImGui::CollapsingHeader("Overlays", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!ImGui::BeginTable("overlays", 2, ImGuiTableFlags_SizingStretchSame)) return;
    for (const OverlayInfo& info : kOverlays) {
        ImGui::TableNextColumn();
        ImGui::Checkbox(info.label, &(o.*info.flag));
        tooltip(info.tooltip);
    }
    ImGui::EndTable();
}

void viewSection(App& app) {
    if (!ImGui::CollapsingHeader("View")) return;
    bool com = app.view.frame == ViewFrame::CentreOfMass;
    if (ImGui::Checkbox("centre-of-mass frame (U)", &com))
        setViewFrame(app.view, com ? ViewFrame::CentreOfMass : ViewFrame::World);
    tooltip("The view moves with the centre of mass's velocity u and the arrows show w = v - u "
            "(the walls drift across the view: they move at -u in this frame)");
    if (uiSmallButton("clear trails (C)")) applyAction(app, Action::ClearTrails);
    float scale = app.view.uiScale;
    if (ImGui::SliderFloat("UI scale", &scale, 0.75f, 3.0f, "%.2f")) {
        // Applied when released: rebuilding the font under the cursor would fight the slider.
        app.ui.messages.note = "UI scale applies on release";
    }
    constexpr limits::Range kUiScaleRange{kMinUiScale, kMaxUiScale, ""};
    double applied = app.view.uiScale;
    if (ImGui::IsItemDeactivatedAfterEdit() &&
        acceptTyped(app, "UI scale", scale, app.view.uiScale, kUiScaleRange, applied)) {
        setUiScale(app.view, static_cast<float>(applied));
    }
    typedWarning(app, "UI scale");
    float labels = app.view.labelScale;
    if (ImGui::SliderFloat("scene labels", &labels, kMinLabelScale, kMaxLabelScale, "%.2fx")) {
        app.ui.messages.note = "Label size applies on release";
    }
    tooltip("Size of the block names and numbers in the scene, apart from the UI scale");
    constexpr limits::Range kLabelRange{kMinLabelScale, kMaxLabelScale, ""};
    double labelScale = app.view.labelScale;
    if (ImGui::IsItemDeactivatedAfterEdit() &&
        acceptTyped(app, "scene labels", labels, app.view.labelScale, kLabelRange, labelScale)) {
        app.view.labelScale = static_cast<float>(labelScale);
    }
    typedWarning(app, "scene labels");
    ImGui::Checkbox("light theme (bright rooms)", &app.view.lightTheme);
    tooltip("Dark text on a light scene and panels: a projector in a lit room washes dark "
            "themes out");
    bool sound = soundOn(app.sim.sound, app.lesson.active());
    if (ImGui::Checkbox("sound (M)", &sound)) applyAction(app, Action::ToggleSound);
    tooltip("A knock at each collision: louder for a larger impulse, higher for a smaller block, "
            "lower on a wall; at most 20 a second (a gas hums). Off by default outside lessons");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    ImGui::SliderFloat("volume", &app.sim.sound.volume, 0.0f, 1.0f, "%.2f",
                       ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::Button("Fit view (F)")) applyAction(app, Action::FitView);
    ImGui::SameLine();
    if (ImGui::Button("Present (F5)")) applyAction(app, Action::TogglePresent);
    ImGui::SameLine();
    if (ImGui::Button("Help (F1)")) app.ui.helpOpen = true;
}

} // namespace

// A narrow screen's sheet: its bar (open or close it, play, step, reset, help) always shows.
void sheetBar(App& app) {
    const float w =
        (ImGui::GetContentRegionAvail().x - 4.0f * ImGui::GetStyle().ItemSpacing.x) / 5.0f;
    if (ImGui::Button(app.view.sheetOpen ? "Close" : "Controls", ImVec2(w * 1.3f, 0)))
        app.view.sheetOpen = !app.view.sheetOpen;
    ImGui::SameLine();
    if (ImGui::Button(app.sim.paused ? "Play" : "Pause", ImVec2(w, 0)))
        applyAction(app, Action::TogglePause);
    ImGui::SameLine();
    if (ImGui::Button("Step", ImVec2(w, 0))) applyAction(app, Action::StepOnce);
    ImGui::SameLine();
    if (ImGui::Button("Reset", ImVec2(w, 0))) applyAction(app, Action::Reset);
    ImGui::SameLine();
    if (ImGui::Button("Help", ImVec2(-1.0f, 0))) app.ui.helpOpen = !app.ui.helpOpen;
}

void drawControlsPanel(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    float width = static_cast<float>(panelWidth(app.view.uiScale, io.DisplaySize.x));
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                             ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                             ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (app.view.layout.sheet) { // along the bottom, the screen's width
        const ScreenRect& r = app.view.layout.panel;
        width = static_cast<float>(r.width);
        ImGui::SetNextWindowPos(ImVec2(static_cast<float>(r.x), static_cast<float>(r.y)));
        ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(r.height)));
        flags |= ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar;
    } else {
        ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y), ImGuiCond_Always);
    }
    if (!ImGui::Begin("Controls", nullptr, flags)) {
        ImGui::End();
        return;
    }
    recordShownWindow(app, "Controls");
    if (app.view.layout.sheet) {
        sheetBar(app);
        if (!app.view.sheetOpen) {
            ImGui::End();
            return;
        }
    }
    const WorldSettings before = app.sim.world().settings;
    ImGui::PushItemWidth(width * 0.52f);
    scenePicker(app);
    if (!app.sim.scene.description.empty()) {
        // At most three lines; the rest scrolls (the panel itself must not, at 720p).
        const float lines = ImGui::GetTextLineHeightWithSpacing() * 3.0f;
        const float wrap = ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ScrollbarSize;
        const float needed =
            ImGui::CalcTextSize(app.sim.scene.description.c_str(), nullptr, false, wrap).y;
        ImGui::BeginChild("##description", ImVec2(0.0f, std::min(lines, needed + 2.0f)));
        ImGui::PushStyleColor(ImGuiCol_Text, uiDimColor());
        textWrappedAtSpaces(app.sim.scene.description);
        ImGui::PopStyleColor();
        ImGui::EndChild();
    }
    if (!app.ui.messages.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, uiErrorColor());
        textWrappedAtSpaces(app.ui.messages.error);
        ImGui::PopStyleColor();
        if (uiSmallButton("dismiss")) app.ui.messages.error.clear();
    } else if (!app.ui.messages.note.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, uiNoteColor());
        textWrappedAtSpaces(app.ui.messages.note);
        ImGui::PopStyleColor();
    }
    lessonSection(app);
    ImGui::Separator();
    runSection(app);
    // Play, Step and Reset stay in view: the sections below scroll on their own.
    // Flattened: the arrow keys go on from Reset into the sections (no Space to enter them).
    ImGui::BeginChild("##sections", ImVec2(0.0f, 0.0f), false, ImGuiWindowFlags_NavFlattened);
    ImGui::PushItemWidth(width * 0.52f);
    simulationSection(app);
    physicsSection(app);
    overlaysSection(app.view.show);
    selectedSection(app);
    statisticsSection(app.sim.run, app.ui);
    viewSection(app);
    fileSection(app);
    compareSection(app);
    ImGui::PopItemWidth();
    ImGui::EndChild();
    ImGui::PopItemWidth();
    ImGui::End();
    if (settingsDiffer(before, app.sim.world().settings)) app.sim.noteEdit(false);
}
