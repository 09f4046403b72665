// The lesson's caption bar: across the top of the scene, "n / N · title" large, the keys (in
// present mode the method and t: lessonBarStatus) beside it, the caption under it, then the
// question ("Predict: ...", at the setup and while the step plays; its answer at the moment) and
// the key to press next. The one caption of a lesson, presenting or
// not (present mode's one-line caption is for scenes). Opaque, so nothing shows through; its
// height is kept in app.view.captionHeight and the scene's viewport starts below it. In present
// mode it is the scene's caption, not a window: --layout-json lists no window there.
#include "app_frame.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <imgui.h>

#include <string>

void drawLessonCaption(App& app) {
    const LessonSession& s = app.lesson;
    const LessonStep* step = s.step();
    if (!step) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float left = app.view.uiVisible && !app.view.presentMode && !app.view.layout.sheet
                           ? static_cast<float>(panelWidth(app.view.uiScale, io.DisplaySize.x))
                           : 0.0f;
    ImGui::SetNextWindowPos(ImVec2(left, 0.0f), ImGuiCond_Always);
    const float width = io.DisplaySize.x - left; // fixed width, the height follows the text
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f),
                                        ImVec2(width, io.DisplaySize.y * 0.5f));
    ImGui::SetNextWindowBgAlpha(1.0f);
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
        ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (!ImGui::Begin("Lesson caption", nullptr, flags)) {
        ImGui::End();
        return;
    }
    if (!app.view.presentMode) recordShownWindow(app, "Lesson caption");
    ImGui::PushFont(uiCaptionFont()); // slide-sized, whatever the UI scale (ui_style.h)
    const std::string heading = lessonHeading(s);
    ImGui::SetWindowFontScale(1.25f);
    ImGui::TextUnformatted(heading.c_str());
    ImGui::SetWindowFontScale(1.0f);
    const std::string status = lessonBarStatus(
        app.view.presentMode, app.sim.world().settings.method, app.sim.world().time);
    // Beside the heading where it fits, else on a line of its own: never cut at the bar's edge
    // (a long title left "PageDown next, PageUp back, R res" at 1920x1080).
    const float headingRight = ImGui::GetItemRectMax().x;
    const float statusWidth = ImGui::CalcTextSize(("   " + status).c_str()).x;
    if (headingRight + ImGui::GetStyle().ItemSpacing.x + statusWidth <=
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
        ImGui::SameLine();
    if (app.view.presentMode)
        ImGui::Text("   %s", status.c_str());
    else
        ImGui::TextColored(uiDimColor(), "   %s", status.c_str());
    ImGui::PushTextWrapPos(0.0f);
    for (const LessonLine& line : lessonCaption(s)) {
        switch (line.kind) {
        case LessonLine::Kind::Caption:
            ImGui::TextUnformatted(line.text.c_str());
            break;
        case LessonLine::Kind::Question:
            ImGui::TextColored(uiQuestionColor(), "%s", line.text.c_str());
            break;
        case LessonLine::Kind::Answer:
            ImGui::TextColored(uiNoteColor(), "%s", line.text.c_str());
            break;
        case LessonLine::Kind::Hint:
        case LessonLine::Kind::GoTo:
            ImGui::TextColored(uiDimColor(), "%s", line.text.c_str());
            break;
        }
    }
    ImGui::PopTextWrapPos();
    ImGui::PopFont();
    app.view.captionHeight = ImGui::GetWindowHeight();
    ImGui::End();
}
