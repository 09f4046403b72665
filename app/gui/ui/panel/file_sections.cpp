#include "file_sections.h"

#include "app_frame.h"
#include "imgui_ext.h"
#include "save_naming.h"
#include "text_format.h"
#include "typed_field.h"
#include "ui_style.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>
#include <string>

namespace {

// `name` as a combo `room` px wide shows it: whole where it fits, else its first words that fit
// with "..." after them (ImGui would cut it mid-letter at the arrow).
std::string fittedName(const std::string& name, float room) {
    if (ImGui::CalcTextSize(name.c_str()).x <= room) return name;
    for (std::size_t end = name.rfind(' '); end != std::string::npos && end > 0;
         end = name.rfind(' ', end - 1)) {
        const std::string shown = name.substr(0, end) + "...";
        if (ImGui::CalcTextSize(shown.c_str()).x <= room) return shown;
    }
    return name; // not even its first word fits: cut as ImGui cuts it
}

} // namespace

void scenePicker(App& app) {
    const char* copyLink = "Copy link";
    const ImGuiStyle& style = ImGui::GetStyle();
    const float copyWidth = app.ui.inBrowser ? ImGui::CalcTextSize(copyLink).x +
                                                   2.0f * style.FramePadding.x + style.ItemSpacing.x
                                             : 0.0f;
    ImGui::SetNextItemWidth(-1.0f - copyWidth);
    // The preview's room: the combo's width less its arrow and its padding.
    const float room = ImGui::GetContentRegionAvail().x - copyWidth - ImGui::GetFrameHeight() -
                       2.0f * style.FramePadding.x;
    const std::string& name = app.sim.scene.name;
    // A scene changed since it was loaded is marked so: its name describes the file ("Momentum
    // example, C = 1"), which is no longer what is on screen once C or a mass has changed.
    const char* edited = app.sim.unsavedEdits() ? " (edited)" : "";
    const std::string preview =
        name.empty() ? "(no scene)"
                     : fittedName(name, room - ImGui::CalcTextSize(edited).x) + edited;
    // Taller than the default 8 rows: every shipped scene at once, in the lecture's order.
    if (ImGui::BeginCombo("##scene", preview.c_str(), ImGuiComboFlags_HeightLargest)) {
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
    const std::string whole = !name.empty() && preview != name ? name + "\n\n" : "";
    tooltip((whole + "The shipped scenes in the lecture's order (app/scenes/lecture_order.txt), "
                     "and lessons (lessons/)")
                .c_str());
    if (!app.ui.inBrowser) return;
    ImGui::SameLine();
    if (ImGui::Button(copyLink)) app.ui.copyLinkRequested = true;
    tooltip("A link for what is on screen: the scene (edited, it travels inside the link), the "
            "method, the overlays, the frame, the lesson's step. The address bar follows too.");
}

namespace {

void editLogButton(App& app) {
    const std::size_t count = app.sim.editsSinceLoad().size();
    const std::string label = "Save edit log (" + std::to_string(count) + ")";
    if (ImGui::Button(label.c_str())) saveEditLog(app);
    tooltip("What was changed since the scene was loaded or R (every edit, undo and redo with its "
            "frame) as a JSON-lines edit log: sandbox --edits FILE and sandbox-cli run --edits "
            "FILE replay it (docs/edits.md)");
}

} // namespace

void fileSection(App& app) {
    if (!ImGui::CollapsingHeader("Open and save")) return;
    if (app.ui.inBrowser) {
        if (ImGui::Button("Open a scene file...")) app.ui.filePickerRequested = true;
        tooltip("The browser's file dialog; or drop a .json file on the page (a .csv is a trace "
                "of your engine: the Compare section)");
        if (ImGui::Button("Save (download)")) applyAction(app, Action::Save);
        tooltip("Downloads the current state as a scene file (format v1) named after the scene; "
                "Ctrl+S");
        editLogButton(app);
        return;
    }
    editLogButton(app);
    ImGui::InputTextWithHint("##open", "path/to/scene.json", &app.ui.openPath);
    ImGui::SameLine();
    if (ImGui::Button("Open") && !app.ui.openPath.empty()) loadScene(app, app.ui.openPath);
    if (ImGui::Button(keyedLabel("Save as...", Action::Save, app.ui.touchUi).c_str()))
        applyAction(app, Action::Save);
    tooltip("Save the current state as a scene file (format v1): asks for a name");
}

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
