// The controls panel: scene, run control, simulation settings, the selected block, statistics
// and view options, bound to App every frame (immediate mode: no state of its own).
#include "app_config.h"
#include "app_frame.h"
#include "overlay_window.h"
#include "save_naming.h"
#include "ui_style.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
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
    if (ImGui::Button(s.asking() ? "Answer >" : "Next >", ImVec2(w, 0)))
        applyAction(app, Action::LessonNext);
    tooltip("PageDown (or Right, with thrust off)");
    ImGui::SameLine();
    if (ImGui::Button("Restart (R)", ImVec2(w, 0))) applyAction(app, Action::Reset);
    const float rows = std::min<float>(8.0f, static_cast<float>(s.lesson->steps.size()));
    ImGui::BeginChild("##steps", ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing()));
    for (std::size_t i = 0; i < s.lesson->steps.size(); ++i) {
        const std::string label =
            std::to_string(i + 1) + ". " + s.lesson->steps[i].title + "##step" + std::to_string(i);
        const bool current = i == s.current;
        if (ImGui::Selectable(label.c_str(), current)) enterStep(app, i);
        if (current && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
    }
    ImGui::EndChild();
    if (ImGui::SmallButton("close lesson")) closeLesson(app);
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
    if (ImGui::SmallButton("first difference")) goToFirstDifference(app);
    ImGui::SameLine();
    if (ImGui::SmallButton("compare again")) compareTraceAgain(app);
    tooltip("With the current settings (the method chosen above), from the start");
    ImGui::SameLine();
    if (ImGui::SmallButton("close")) closeTrace(app);
}

void runSection(App& app) {
    const float w = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3;
    if (ImGui::Button(app.sim.paused ? "Play  (P)" : "Pause (P)", ImVec2(w, 0))) {
        applyAction(app, Action::TogglePause);
    }
    ImGui::SameLine();
    if (ImGui::Button("Step (N)", ImVec2(w, 0))) applyAction(app, Action::StepOnce);
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)", ImVec2(w, 0))) applyAction(app, Action::Reset);
    tooltip("Blocks and time back to the start; keeps the method, C, g, frame rate, substeps");
    ImGui::Checkbox("Slow motion (Space)", &app.sim.slowMotion);
    tooltip("5 simulation frames per second, as in the lecture's demo");
    ImGui::SameLine();
    if (ImGui::Button("Reset to file")) applyAction(app, Action::ResetToFile);
    tooltip("Shift+R: everything as the scene file has it, settings included");
}

void simulationSection(App& app) {
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    WorldSettings& s = app.sim.world().settings;
    int method = static_cast<int>(s.method);
    constexpr int kMethods = static_cast<int>(Method::Count);
    const char* names[kMethods];
    for (int k = 0; k < kMethods; ++k) names[k] = methodName(static_cast<Method>(k));
    if (ImGui::Combo("method (S)", &method, names, kMethods))
        s.method = static_cast<Method>(method);
    tooltip("perfect: events in time order, no overlap\nmove-and-correct: move, then push "
            "apart\nturn-based: one body at a time");
    float c = static_cast<float>(s.bounciness);
    const float sliderWidth = ImGui::CalcItemWidth();
    if (ImGui::SliderFloat("bounciness C", &c, 0.0f, 1.0f, "%.2f")) {
        acceptTyped(app, "bounciness C", c, s.bounciness, limits::kBounciness, s.bounciness);
    }
    tooltip("Coefficient of restitution: 1 elastic, 0 perfectly inelastic");
    if (app.log.verbose && !app.log.layoutLogged) {
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        std::printf("widget bounciness %d %d %d %d\n", static_cast<int>(a.x), static_cast<int>(a.y),
                    static_cast<int>(sliderWidth), static_cast<int>(b.y - a.y));
        app.log.layoutLogged = true;
    }
    typedWarning(app, "bounciness C");
    float g[2] = {static_cast<float>(s.gravity.x), static_cast<float>(s.gravity.y)};
    if (ImGui::SliderFloat2("##gravity", g, -20.0f, 20.0f, "%.2f")) {
        // Ctrl+click types a value beyond the slider: any within the limits is taken.
        acceptTyped2(app, "gravity", g, s.gravity, limits::kGravity, s.gravity);
    }
    tooltip("Gravity (x, y) in m/s² (Ctrl+click to type a value)");
    ImGui::SameLine();
    if (ImGui::SmallButton("0")) s.gravity = Vec2{0.0, 0.0};
    if (ImGui::IsItemActivated()) app.ui.typedWarning.note("gravity", TypedValue{});
    tooltip("No gravity");
    ImGui::SameLine();
    if (ImGui::SmallButton("9.81")) s.gravity = Vec2{0.0, -9.81};
    if (ImGui::IsItemActivated()) app.ui.typedWarning.note("gravity", TypedValue{});
    tooltip("Gravity 9.81 m/s² down");
    ImGui::SameLine();
    ImGui::TextUnformatted("g");
    typedWarning(app, "gravity");
    float hz = static_cast<float>(1.0 / s.dt);
    if (ImGui::SliderFloat("frame rate", &hz, 5.0f, 240.0f, "%.0f Hz")) {
        double rate = 1.0 / s.dt;
        if (acceptTyped(app, "frame rate", hz, rate, limits::kFrameRate, rate)) s.dt = 1.0 / rate;
    }
    tooltip("Simulation frames per simulated second: dt = 1 / rate");
    typedWarning(app, "frame rate");
    int substeps = s.substeps;
    if (ImGui::SliderInt("substeps", &substeps, 1, 32, "%d")) {
        double k = s.substeps;
        if (acceptTyped(app, "substeps", substeps, k, limits::kSubsteps, k)) {
            s.substeps = static_cast<int>(k);
        }
    }
    typedWarning(app, "substeps");
    float scale = static_cast<float>(app.sim.timeScale);
    if (ImGui::SliderFloat("time scale", &scale, 0.05f, 4.0f, "%.2fx",
                           ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "time scale", scale, app.sim.timeScale, limits::kTimeScale,
                    app.sim.timeScale);
    }
    typedWarning(app, "time scale");
}

// A combo over the engine's own list of names (resolveName, integratorName): no second list.
template <typename E> bool enumCombo(const char* label, E& value, const char* (*name)(E)) {
    bool changed = false;
    if (ImGui::BeginCombo(label, name(value))) {
        for (int i = 0; i < static_cast<int>(E::Count); ++i) {
            const E e = static_cast<E>(i);
            if (ImGui::Selectable(name(e), e == value) && e != value) {
                value = e;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
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
    WorldSettings& s = app.sim.world().settings;
    enumCombo("resolve", s.resolve, resolveName);
    tooltip("momentum: with Newton, the lecture's formula u = (m1·v1 + m2·v2)/(m1 + m2), "
            "v' = u - C·(v - u)\nreflect: without Newton, each body reverses its own component "
            "as off a wall, v' = -C·v (momentum is not kept)\n(slide \"Demo: bouncing squares; "
            "with/without Newton\")");
    enumCombo("integrator", s.integrator, integratorName);
    tooltip("semi-implicit-euler: v += a·h, then x += v·h (the lecture's)\nexplicit-euler: x "
            "moves with the old v\nexact: x += v·h + a·h²/2, the parabola (slide \"It is just an "
            "approximation of the true movement!\")");
    float drag = static_cast<float>(s.drag);
    if (ImGui::SliderFloat("drag k", &drag, 0.0f, 1000.0f, "%.3g kg/m³",
                           ImGuiSliderFlags_Logarithmic)) {
        acceptTyped(app, "drag k", drag, s.drag, limits::kDrag, s.drag);
    }
    tooltip("Quadratic drag: force -k·A·|v|·v, A = w·h; terminal speed sqrt(m·g/(k·A)). Air 1.2, "
            "water 1000 (slide \"Viscosity/drag: a feather falls slower than a stone\"; "
            "Ctrl+click to type)");
    typedWarning(app, "drag k");
    ImGui::TextColored(uiDimColor(), "Mistakes (the Tips slides' bugs)");
    for (int m = 0; m < static_cast<int>(Mistake::Count); ++m) {
        const Mistake mistake = static_cast<Mistake>(m);
        bool on = s.has(mistake);
        if (ImGui::Checkbox(mistakeName(mistake), &on)) s.set(mistake, on);
        tooltip((std::string("Slide: \"") + mistakeSlide(mistake) + "\"").c_str());
    }
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
    float f[2] = {static_cast<float>(b.force.x), static_cast<float>(b.force.y)};
    Vec2 force = b.force;
    if (ImGui::DragFloat2("force", f, 0.05f, -1000.0f, 1000.0f, "%.2f N") &&
        acceptTyped2(app, "force", f, b.force, limits::kForce, force) &&
        acceptAcceleration(app, "force", force, b.mass)) {
        b.force = force;
        app.sim.noteEdit(true);
    }
    tooltip("A constant force on the block (N), a = F/m (Ctrl+click to type); its arrow is drawn "
            "with the arrows overlay");
    typedWarning(app, "force");
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
        float mass = static_cast<float>(b.mass);
        double newMass = b.mass;
        if (ImGui::SliderFloat("mass", &mass, 0.01f, 1000.0f, "%.3g kg",
                               ImGuiSliderFlags_Logarithmic) &&
            acceptTyped(app, "mass", mass, b.mass, limits::kMass, newMass) &&
            acceptAcceleration(app, "mass", b.force, newMass)) {
            b.mass = newMass;
            app.sim.noteEdit(true);
        }
        typedWarning(app, "mass");
        blockForceField(app, b);
    } else {
        ImGui::TextColored(uiDimColor(), "mass: infinite");
    }
    float size[2] = {static_cast<float>(b.size.x), static_cast<float>(b.size.y)};
    if (ImGui::DragFloat2("size", size, 0.02f, 0.05f, 50.0f, "%.2f m")) {
        Vec2 wanted = b.size;
        if (acceptTyped2(app, "size", size, b.size, limits::kSize, wanted) &&
            !app.sim.setBlockSize(i, wanted)) {
            app.ui.typedWarning.note(
                "size", {false, 0.0, "size: that size would overlap another block or a wall"});
        }
    }
    typedWarning(app, "size");
    if (b.kind != BodyKind::Static) {
        float v[2] = {static_cast<float>(b.velocity.x), static_cast<float>(b.velocity.y)};
        if (ImGui::DragFloat2("velocity", v, 0.05f, -1000.0f, 1000.0f, "%.2f m/s") &&
            acceptTyped2(app, "velocity", v, b.velocity, limits::kSpeed, b.velocity)) {
            app.sim.noteEdit(true);
        }
        typedWarning(app, "velocity");
    }
    ImGui::TextColored(uiDimColor(), "position (%.2f, %.2f) m", b.position.x, b.position.y);
    if (ImGui::Button("Delete block")) deleteSelected(app);
}

void statisticsSection(const Run& run, const UiState& ui) {
    if (!ImGui::CollapsingHeader("Statistics")) return;
    const StepStats& s = run.stats;
    if (!ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) return;
    statRow("collisions / frame", "%.0f", s.collisions);
    statRow("events / frame", "%.0f", s.events);
    statRow("largest overlap", "%.4f m", s.maxPenetration);
    statRow("event-cap hits", "%.0f", static_cast<double>(run.totals.eventCapHits));
    statRow("step time", "%.3f ms", s.stepMs);
    statRow("collisions (total)", "%.0f", static_cast<double>(run.totals.collisions));
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
    if (ImGui::SmallButton("clear trails (C)")) applyAction(app, Action::ClearTrails);
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

void drawControlsPanel(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    const float width = static_cast<float>(panelWidth(app.view.uiScale, io.DisplaySize.x));
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (!ImGui::Begin("Controls", nullptr, flags)) {
        ImGui::End();
        return;
    }
    recordShownWindow(app, "Controls");
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
        if (ImGui::SmallButton("dismiss")) app.ui.messages.error.clear();
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
