// The lesson's caption bar: across the top of the scene, "n / N · title" large, the keys (in
// present mode the method and t: lessonBarStatus) beside it, the caption under it, then the
// question ("Predict: ...", with its choices lettered A-D, at the setup and while the step plays;
// its answer at the moment, or why there is none) and the key to press next. The one caption of a
// lesson, presenting or not (present mode's one-line caption is for scenes). Opaque, so nothing
// shows through; its height is kept in app.view.captionHeight and the scene's viewport starts below
// it. In present mode it is the scene's caption, not a window: --layout-json lists no window there.
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
    // Computed from the world as it is (lesson_prompt.h): true after any change of the lecturer's;
    // composed once (lessonCaption), which the page's screen-reader text reads too. Wrapped at
    // spaces and never inside an equation's number (wrapFormula: "0.\n5" is not 0.5).
    const auto said = [](const ImVec4& color, const std::string& text) {
        ImGui::PushStyleColor(ImGuiCol_Text, color);
        textWrappedFormula(text);
        ImGui::PopStyleColor();
    };
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    const float gap = ImGui::CalcTextSize("    ").x;
    for (const LessonLine& line : lessonCaption(s, app.sim)) {
        switch (line.kind) {
        case LessonLine::Kind::Caption:
            textWrappedFormula(line.text);
            break;
        case LessonLine::Kind::Question:
            said(uiQuestionColor(), line.text);
            break;
        case LessonLine::Kind::Choice: {
            // The choices after the question and side by side where they fit (a short question
            // and its choices take one line), each whole.
            const float width = ImGui::CalcTextSize(line.text.c_str()).x;
            if (ImGui::GetItemRectMax().x + gap + width <= right) ImGui::SameLine(0.0f, gap);
            said(uiQuestionColor(), line.text);
            break;
        }
        case LessonLine::Kind::Answer:
        case LessonLine::Kind::NoAnswer:
            said(uiNoteColor(), line.text);
            break;
        case LessonLine::Kind::Hint:
        case LessonLine::Kind::GoTo:
            ImGui::TextColored(uiDimColor(), "%s", line.text.c_str());
            break;
        }
    }
    ImGui::PopFont();
    app.view.captionHeight = ImGui::GetWindowHeight();
    ImGui::End();
}
