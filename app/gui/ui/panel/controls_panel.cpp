// The controls panel: scene, run control, simulation settings, the selected block, statistics
// and view options, bound to App every frame (immediate mode: no state of its own). The sections
// that edit the world and its blocks are settings_sections.cpp's, the scene's file
// file_sections.cpp's; typed values typed_field.cpp's.
#include "app_config.h"
#include "app_frame.h"
#include "edit_words.h"
#include "file_sections.h"
#include "imgui_ext.h"
#include "overlay_window.h"
#include "save_naming.h"
#include "settings_sections.h"
#include "slider.h"
#include "text_format.h"
#include "typed_field.h"
#include "ui_style.h"
#include "whole_rows.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace {

void statRow(const char* name, const char* fmt, double value) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    ImGui::Text(fmt, value);
}

// A touch screen with a panel column (a tablet): the bar (in a lesson its Prev / Play / Restart,
// else Play, Step and Reset) is pinned at the panel's top and the rest scrolls under it, so that
// the windows docked under the panel (a lesson's plots at its moment) never scroll the bar away.
// A narrow screen's sheet has its own bar (sheetBar).
bool touchPanelBar(const App& app) {
    return app.ui.touchUi && !app.view.layout.sheet;
}

// The height the lesson section takes above its step list: its header, the lesson's name, the
// Prev / Next / Restart row (unless pinned above) and the "close lesson" button under the list.
float lessonFrameHeight(const App& app) {
    const LessonSession& s = app.lesson;
    if (!s.active()) return 0.0f;
    const float row = ImGui::GetFrameHeightWithSpacing();
    const float name = ImGui::CalcTextSize(s.lesson->name.c_str(), nullptr, false,
                                           ImGui::GetContentRegionAvail().x)
                           .y +
                       ImGui::GetStyle().ItemSpacing.y;
    return (touchPanelBar(app) ? 2.0f : 3.0f) * row + name;
}

// The lesson's Prev, Play (Next at the moment) and Restart, in a row the panel's width.
void lessonButtons(App& app) {
    const LessonSession& s = app.lesson;
    const float w = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3;
    if (ImGui::Button("< Prev", ImVec2(w, 0))) applyAction(app, Action::LessonPrevious);
    tooltip("PageUp (or Left, with thrust off)");
    ImGui::SameLine();
    if (ImGui::Button(s.phase == LessonSession::Phase::Setup ? "Play >" : "Next >", ImVec2(w, 0)))
        applyAction(app, Action::LessonNext);
    tooltip("PageDown (or Right, with thrust off)");
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Restart", Action::Reset, app.ui.touchUi).c_str(), ImVec2(w, 0)))
        applyAction(app, Action::Reset);
    tooltip("R: the step again from its setup, keeping the method and settings you changed; "
            "Shift+R: the step as written");
}

// The open lesson's steps: click one to go there. At most `maxRows` rows of the list show, whole:
// its scroll follows the current step (with the steps around it) and stops on whole rows.
void lessonSection(App& app, int maxRows) {
    LessonSession& s = app.lesson;
    if (!s.active()) return;
    if (!ImGui::CollapsingHeader("Lesson", ImGuiTreeNodeFlags_DefaultOpen)) return;
    textWrappedAtSpaces(s.lesson->name);
    if (!touchPanelBar(app)) lessonButtons(app);
    const int steps = static_cast<int>(s.lesson->steps.size());
    const int rows = std::max(1, std::min({maxRows, 8, steps}));
    uiBeginRows();
    const float rowHeight = std::round(ImGui::GetTextLineHeightWithSpacing());
    // With touch sizes a one-row list has no scroll bar: its bar would be shorter than a
    // fingertip (a finger's swipe scrolls the list; Prev and Next step through it).
    const ImGuiWindowFlags listFlags =
        app.ui.touchUi && rows == 1 ? ImGuiWindowFlags_NoScrollbar : ImGuiWindowFlags_None;
    ImGui::BeginChild("##steps", ImVec2(0.0f, static_cast<float>(rows) * rowHeight), false,
                      listFlags);
    WholeRows whole;
    const int current = static_cast<int>(s.current);
    if (current != app.ui.stepListFollowed || rows != app.ui.stepListRows ||
        ImGui::IsWindowAppearing()) {
        // The current step in the middle (one more row after it than before when even).
        const int first = std::clamp(current - (rows - 1) / 2, 0, std::max(0, steps - rows));
        ImGui::SetScrollY(static_cast<float>(first) * rowHeight);
        app.ui.stepListFollowed = current;
        app.ui.stepListRows = rows;
    } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        // The wheel or the keyboard scrolled it: on to the nearest whole row.
        const float y = ImGui::GetScrollY();
        const float snapped = std::round(y / rowHeight) * rowHeight;
        if (std::fabs(snapped - y) >= 0.5f) ImGui::SetScrollY(snapped);
    }
    for (int i = 0; i < steps; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const std::string label =
            std::to_string(i + 1) + ". " + s.lesson->steps[k].title + "##step" + std::to_string(i);
        if (ImGui::Selectable(label.c_str(), i == current)) enterStep(app, k);
    }
    // The list's height a whole number of rows (the last row's spacing too), so that scrolled to
    // its end it shows whole rows.
    ImGui::Dummy(ImVec2(0.0f, 0.0f));
    whole.end();
    ImGui::EndChild();
    uiEndRows();
    if (uiSmallButton("close lesson")) closeLesson(app);
    tooltip("Leave the lesson; the current scene stays");
}

// The journal of what was changed since the scene was loaded (or R), as an edit log.
// Undo and Redo (Ctrl+Z, Ctrl+Y): each says what it would do, and is dim when there is nothing.
void undoButtons(App& app) {
    const float w = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2;
    const struct {
        const char* label;
        Action action;
        const AppliedEdit* next;
        bool undone;
    } buttons[] = {{"Undo", Action::Undo, app.sim.edits.nextUndo(), true},
                   {"Redo", Action::Redo, app.sim.edits.nextRedo(), false}};
    for (const auto& b : buttons) {
        if (b.action == Action::Redo) ImGui::SameLine();
        ImGui::BeginDisabled(!b.next);
        if (ImGui::Button(keyedLabel(b.label, b.action, app.ui.touchUi).c_str(), ImVec2(w, 0)))
            applyAction(app, b.action);
        ImGui::EndDisabled();
        if (b.next && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s: %s", b.label,
                              editChangeText(*b.next, b.undone, app.sim.labels).c_str());
    }
}

// Play on a touch screen: in a lesson, at the setup, it plays to the step's moment and stops
// there (as PageDown), and at the moment it is Next (the next step); else Play or Pause.
struct PlayButton {
    const char* label;
    Action action;
};
PlayButton touchPlayButton(const App& app) {
    const LessonSession& s = app.lesson;
    if (s.active() && s.phase == LessonSession::Phase::Setup) return {"Play", Action::LessonNext};
    if (s.active() && s.phase == LessonSession::Phase::Moment && s.pauses() &&
        s.current + 1 < s.lesson->steps.size())
        return {"Next", Action::LessonNext};
    return {app.sim.paused ? "Play" : "Pause", Action::TogglePause};
}

// Play (Pause), Step and Reset, in a row the panel's width.
void runButtons(App& app) {
    const float w = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3;
    const bool touch = app.ui.touchUi;
    const PlayButton play =
        touch ? touchPlayButton(app)
              : PlayButton{app.sim.paused ? "Play" : "Pause", Action::TogglePause};
    if (ImGui::Button(keyedLabel(play.label, play.action, touch).c_str(), ImVec2(w, 0)))
        applyAction(app, play.action);
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Step", Action::StepOnce, touch).c_str(), ImVec2(w, 0)))
        applyAction(app, Action::StepOnce);
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Reset", Action::Reset, touch).c_str(), ImVec2(w, 0)))
        applyAction(app, Action::Reset);
    tooltip("Blocks and time back to the start; keeps the method, C, g, frame rate, substeps");
}

void runSection(App& app) {
    // The sheet has them in its bar; a tablet's panel outside a lesson pinned at its top
    // (touchPanelBar).
    if (!app.view.layout.sheet && !(touchPanelBar(app) && !app.lesson.active())) runButtons(app);
    ImGui::Checkbox(keyedLabel("Slow motion", Action::ToggleSlowMotion, app.ui.touchUi).c_str(),
                    &app.sim.slowMotion);
    tooltip("5 simulation frames per second, as in the lecture's demo");
    ImGui::SameLine();
    if (ImGui::Button("Reset to file")) applyAction(app, Action::ResetToFile);
    tooltip("Shift+R: everything as the scene file has it, settings included");
    undoButtons(app);
}

// Returns whether it is open (the steps are timed only while it is: SimulationSession's
// stepTimeShown).
bool statisticsSection(const Run& run, const UiState& ui) {
    if (!ImGui::CollapsingHeader("Statistics")) return false;
    const StepStats& s = run.stats;
    if (!ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) return true;
    statRow("collisions / frame", "%.0f", s.collisions);
    statRow("resting contacts / frame", "%.0f", s.contacts);
    statRow("events / frame", "%.0f", s.events);
    statRow("largest overlap", "%.4f m", s.maxPenetration);
    statRow("event-cap hits", "%.0f", static_cast<double>(run.totals.eventCapHits));
    if (s.timed) {
        statRow("step time", "%.3f ms", s.stepMs);
    } else { // the step before the section opened (the next one is timed)
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("step time");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("from the next step");
    }
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
    return true;
}

void overlaysSection(Overlays& o, bool touch) {
    if (!ImGui::CollapsingHeader("Overlays", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!ImGui::BeginTable("overlays", 2, ImGuiTableFlags_SizingStretchSame)) return;
    for (const OverlayInfo& info : kOverlays) {
        ImGui::TableNextColumn();
        ImGui::Checkbox(keyedLabel(info.label, actionOfControl(info.name), touch).c_str(),
                        &(o.*info.flag));
        tooltip(info.tooltip);
    }
    ImGui::EndTable();
}

void viewSection(App& app) {
    if (!ImGui::CollapsingHeader("View")) return;
    bool com = app.view.frame == ViewFrame::CentreOfMass;
    if (ImGui::Checkbox(
            keyedLabel("centre-of-mass frame", Action::ToggleFrame, app.ui.touchUi).c_str(), &com))
        setViewFrame(app.view, com ? ViewFrame::CentreOfMass : ViewFrame::World);
    tooltip("The view moves with the centre of mass's velocity u and the arrows show w = v - u "
            "(the walls drift across the view: they move at -u in this frame)");
    if (uiSmallButton(keyedLabel("clear trails", Action::ClearTrails, app.ui.touchUi).c_str()))
        applyAction(app, Action::ClearTrails);
    float scale = app.view.uiScale;
    if (uiSliderFloat("UI scale", &scale, 0.75f, 3.0f, "%.2f")) {
        // Applied when released: rebuilding the font under the cursor would fight the slider.
        app.ui.messages.note = "UI scale applies on release";
    }
    constexpr limits::Range kUiScaleRange{kMinUiScale, kMaxUiScale, ""};
    double applied = app.view.uiScale;
    if (ImGui::IsItemDeactivatedAfterEdit() &&
        acceptTyped(app, "UI scale", scale, "%.2f", app.view.uiScale, kUiScaleRange, applied)) {
        setUiScale(app.view, static_cast<float>(applied));
    }
    typedWarning(app, "UI scale");
    float labels = app.view.labelScale;
    if (uiSliderFloat("scene labels", &labels, kMinLabelScale, kMaxLabelScale, "%.2fx")) {
        app.ui.messages.note = "Label size applies on release";
    }
    tooltip("Size of the block names and numbers in the scene, apart from the UI scale");
    constexpr limits::Range kLabelRange{kMinLabelScale, kMaxLabelScale, ""};
    double labelScale = app.view.labelScale;
    if (ImGui::IsItemDeactivatedAfterEdit() &&
        acceptTyped(app, "scene labels", labels, "%.2fx", app.view.labelScale, kLabelRange,
                    labelScale)) {
        app.view.labelScale = static_cast<float>(labelScale);
    }
    typedWarning(app, "scene labels");
    ImGui::Checkbox("light theme (bright rooms)", &app.view.lightTheme);
    tooltip("Dark text on a light scene and panels: a projector in a lit room washes dark "
            "themes out");
    bool sound = soundOn(app.sim.sound, app.lesson.active());
    if (ImGui::Checkbox(keyedLabel("sound", Action::ToggleSound, app.ui.touchUi).c_str(), &sound))
        applyAction(app, Action::ToggleSound);
    tooltip("A knock at each collision: louder for a larger impulse, higher for a smaller block, "
            "lower on a wall; at most 20 a second (a gas hums). Off by default outside lessons");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    uiSliderFloat("volume", &app.sim.sound.volume, 0.0f, 1.0f, "%.2f",
                  ImGuiSliderFlags_AlwaysClamp);
    const bool touch = app.ui.touchUi;
    if (ImGui::Button(keyedLabel("Fit view", Action::FitView, touch).c_str()))
        applyAction(app, Action::FitView);
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Present", Action::TogglePresent, touch).c_str()))
        applyAction(app, Action::TogglePresent);
    ImGui::SameLine();
    if (ImGui::Button(keyedLabel("Help", Action::ToggleHelp, touch).c_str()))
        app.ui.helpOpen = true;
}

// The scene's description, dim: whole where it fits in `maxLines` lines, else its first
// sentences that do with "(more)" after them, the whole on hovering it. Nothing is cut at an
// edge, and nothing scrolls.
void sceneDescription(const std::string& text, int maxLines) {
    const float width = ImGui::GetContentRegionAvail().x;
    const auto lineCount = [width](const std::string& t) {
        const std::string& wrapped = wrappedAtSpaces(t, width);
        return 1 + static_cast<int>(std::count(wrapped.begin(), wrapped.end(), '\n'));
    };
    const char* more = " (more)";
    std::string shown = text;
    bool cut = false;
    while (lineCount(shown + (cut ? more : "")) > maxLines && shown.size() > 2) {
        const std::size_t end = shown.rfind(". ", shown.size() - 2); // the last sentence's start
        if (end == std::string::npos) break;
        shown.resize(end + 1);
        cut = true;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, uiDimColor());
    textWrappedAtSpaces(cut ? shown + more : shown);
    ImGui::PopStyleColor();
    if (cut) wrappedTooltip(text);
}

} // namespace

// A narrow screen's sheet: its bar (open or close it, play, step, reset, help) always shows.
void sheetBar(App& app) {
    const float w =
        (ImGui::GetContentRegionAvail().x - 4.0f * ImGui::GetStyle().ItemSpacing.x) / 5.0f;
    if (ImGui::Button(app.view.sheetOpen ? "Close" : "Controls", ImVec2(w * 1.3f, 0)))
        app.view.sheetOpen = !app.view.sheetOpen;
    ImGui::SameLine();
    const PlayButton play = touchPlayButton(app); // a narrow screen: a phone
    if (ImGui::Button(play.label, ImVec2(w, 0))) applyAction(app, play.action);
    ImGui::SameLine();
    if (ImGui::Button("Step", ImVec2(w, 0))) applyAction(app, Action::StepOnce);
    ImGui::SameLine();
    if (ImGui::Button("Reset", ImVec2(w, 0))) applyAction(app, Action::Reset);
    ImGui::SameLine();
    if (ImGui::Button("Help", ImVec2(-1.0f, 0))) app.ui.helpOpen = !app.ui.helpOpen;
}

namespace {

// The sections below Play, Step and Reset, `height` px high, scrolling on their own.
void sectionsChild(App& app, float width, float height) {
    ImGui::BeginChild("##sections", ImVec2(0.0f, height), false, imgui_ext::flattenedNavigation());
    WholeRows wholeSections;
    ImGui::PushItemWidth(width * 0.52f);
    simulationSection(app);
    physicsSection(app);
    overlaysSection(app.view.show, app.ui.touchUi);
    selectedSection(app);
    app.sim.stepTimeShown = statisticsSection(app.sim.run, app.ui);
    viewSection(app);
    fileSection(app);
    compareSection(app);
    pollSection(app);
    ImGui::PopItemWidth();
    wholeSections.end();
    ImGui::EndChild();
}

} // namespace

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
        // The column's top, under a lesson's caption bar: windows docked under the panel (the
        // plots) take its bottom.
        const ScreenRect& r = app.view.layout.panel;
        const float height = r.height > 0.0 ? static_cast<float>(r.height) : io.DisplaySize.y;
        ImGui::SetNextWindowPos(ImVec2(0, static_cast<float>(r.y)), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
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
    const bool pinned = touchPanelBar(app);
    if (pinned) { // the bar; the rest scrolls under it
        if (app.lesson.active())
            lessonButtons(app);
        else
            runButtons(app);
        ImGui::Separator();
        ImGui::BeginChild("##under the bar", ImVec2(0.0f, 0.0f), false,
                          imgui_ext::flattenedNavigation());
    }
    WholeRows whole;
    ImGui::PushItemWidth(width * 0.52f);
    scenePicker(app);
    // The panel's own height is shared so that it need not scroll: under the lesson, Play, Step
    // and Reset and 4 rows of the sections that scroll; the scene's description leaves room for
    // 3 rows of the step list (a third of the panel at most, 2 lines at least), and the list
    // shows the rows that fit (the current step at least).
    const float row = ImGui::GetFrameHeightWithSpacing();
    constexpr int kLeastSectionRows = 4, kLeastStepRows = 3;
    // Under the lesson: Play, Step and Reset; Slow motion; Undo and Redo; then the sections.
    const float under = ImGui::GetStyle().ItemSpacing.y + 1.0f + (3 + kLeastSectionRows) * row;
    const float lessonFrame = lessonFrameHeight(app);
    const float stepRow = ImGui::GetTextLineHeightWithSpacing();
    if (!app.sim.scene.description.empty()) {
        const float avail = ImGui::GetContentRegionAvail().y;
        const float room = app.lesson.active()
                               ? avail - under - lessonFrame - kLeastStepRows * stepRow
                               : avail - under;
        const float height = std::min(avail / 3.0f, room);
        sceneDescription(app.sim.scene.description,
                         std::max(2, static_cast<int>(height / ImGui::GetFontSize())));
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
    lessonSection(
        app, static_cast<int>((ImGui::GetContentRegionAvail().y - under - lessonFrame) / stepRow));
    ImGui::Separator();
    runSection(app);
    // Play, Step and Reset stay in view: the sections below scroll on their own.
    // Flattened: the arrow keys go on from Reset into the sections (no Space to enter them).
    // It shows whole rows only (WholeRows): a row its bottom edge would cut is hidden, and with
    // no room for one row (a short panel over a lesson's plots) the sections are not drawn.
    const float rows = std::floor(ImGui::GetContentRegionAvail().y / row);
    if (rows >= 1.0f) sectionsChild(app, width, rows * row);
    ImGui::PopItemWidth();
    whole.end();
    if (pinned) ImGui::EndChild();
    ImGui::End();
}
