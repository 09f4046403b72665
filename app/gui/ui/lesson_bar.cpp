// The lesson's caption bar: across the top of the screen, over the panel too (a slide's title
// area), "n / N · title" large with the status beside it (the key to press next, or in present
// mode the method and t: lessonBarStatus), the step's caption under it, then the question
// ("Predict: ...", at the setup and while the step plays; its answer at the moment). The one
// caption of a lesson, presenting or not. Opaque.
//
// Its height is planned once for a step on a screen (planBar), not measured every frame: the
// most of what the setup and the moment need, so the scene below keeps one size while the step
// is asked, played and answered (the world keeps its room at the answer), and at most
// kMaxCaptionShare of the screen's height: the question or answer is always whole, the caption
// shows the lines that fit ("... (more)", the whole on hovering it or a click), and where even
// that does not fit a smaller font is tried. The plan's height is app.view.captionHeight, which
// the layout keeps free above the panel, the windows and the scene. In present mode the bar is
// the scene's caption, not a window: --layout-json lists no window there.
#include "app_frame.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

// The heading's size relative to the bar's font.
constexpr float kHeadingScale = 1.25f;

// What the bar shows of a step on a screen, and how high it is: measured when the step, the
// screen or the fonts change (planBar), not every frame.
struct BarPlan {
    std::string key; // the step, the screen and the font it was planned for
    ImFont* font = nullptr;
    std::string caption; // the step's caption as shown: whole, or the lines that fit and "..."
    bool captionCut = false;
    float height = 0.0f; // px: the most the setup's and the moment's texts take
};
BarPlan gPlan;
bool gCaptionOpen = false; // "(more)" clicked: the whole caption, over the scene

// The question's part of the bar at the setup (and while the step plays), or the answer's.
std::string askedText(const LessonStep& step) {
    return step.question.empty() ? "" : "Predict: " + step.question;
}
std::string answeredText(const LessonStep& step) {
    return step.question.empty() ? "" : "Answer: " + step.answer;
}

// The height of `text` wrapped `width` px wide in the current font (0 for none).
float wrappedHeight(const std::string& text, float width) {
    if (text.empty()) return 0.0f;
    return ImGui::CalcTextSize(text.c_str(), nullptr, false, width).y;
}

// The first lines of `text` that take at most `lines` lines wrapped `width` px wide, cut at a
// word and followed by "..." ("" when not even a word fits).
std::string firstLines(const std::string& text, float width, int lines) {
    const float most = static_cast<float>(lines) * ImGui::GetTextLineHeight() + 0.5f;
    std::string best;
    std::size_t end = 0;
    while (end != std::string::npos) {
        end = text.find_first_of(" \n", end + 1);
        const std::string tried = text.substr(0, end) + "...";
        if (wrappedHeight(tried + " (more)", width) > most) break;
        best = tried;
    }
    return best;
}

std::string planKey(const LessonSession& s, float width, float height) {
    return std::to_string(s.current) + "|" + std::to_string(width) + "x" + std::to_string(height) +
           "|" + std::to_string(static_cast<double>(uiCaptionFont()->FontSize)) + "|" +
           std::to_string(static_cast<double>(uiCurrentScale())) + "|" + s.lesson->name;
}

// The bar for the open step on a `width` x `screenHeight` screen, in the first font (the
// slide-sized caption font, then the UI's) in which the heading and the question or answer
// leave room for a line of the caption within kMaxCaptionShare of the height.
BarPlan planBar(const LessonSession& s, float width, float screenHeight) {
    const LessonStep& step = *s.step();
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = width - 2.0f * style.WindowPadding.x;
    const float most = static_cast<float>(kMaxCaptionShare) * screenHeight;
    BarPlan plan;
    plan.key = planKey(s, width, screenHeight);
    for (ImFont* font : {uiCaptionFont(), ImGui::GetFont(), uiCompactFont()}) {
        ImGui::PushFont(font);
        const float line = ImGui::GetTextLineHeight(), gap = style.ItemSpacing.y;
        const float heading = line * kHeadingScale;
        const float asked = std::max(wrappedHeight(askedText(step), wrap),
                                     wrappedHeight(answeredText(step), wrap));
        const float fixed = 2.0f * style.WindowPadding.y + heading + (asked > 0.0f ? gap + asked : 0.0f);
        const float caption = wrappedHeight(step.caption, wrap);
        plan.font = font;
        plan.caption = step.caption;
        plan.captionCut = false;
        plan.height = fixed + (caption > 0.0f ? gap + caption : 0.0f);
        const int room = static_cast<int>(std::floor((most - fixed - gap) / line));
        if (plan.height > most && room >= 1) { // the caption's first lines, "... (more)"
            plan.caption = firstLines(step.caption, wrap, room);
            plan.captionCut = true;
            plan.height = fixed + gap + wrappedHeight(plan.caption + " (more)", wrap);
        }
        ImGui::PopFont();
        if (plan.height <= most) break;
    }
    plan.height = std::ceil(plan.height);
    return plan;
}

} // namespace

void planLessonCaption(App& app) {
    const LessonSession& s = app.lesson;
    if (!s.step()) {
        app.view.captionHeight = 0.0;
        return;
    }
    const ImGuiIO& io = ImGui::GetIO();
    const std::string key = planKey(s, io.DisplaySize.x, io.DisplaySize.y);
    if (key != gPlan.key) {
        gPlan = planBar(s, io.DisplaySize.x, io.DisplaySize.y);
        gCaptionOpen = false;
    }
    app.view.captionHeight = gPlan.height;
}

void drawLessonCaption(App& app) {
    const LessonSession& s = app.lesson;
    const LessonStep* step = s.step();
    if (!step || gPlan.font == nullptr) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    // The planned height; the whole caption ("(more)" clicked) grows it over the scene.
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, gCaptionOpen ? 0.0f : gPlan.height),
                             ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                             ImGuiWindowFlags_NoSavedSettings |
                             ImGuiWindowFlags_NoFocusOnAppearing |
                             ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (gCaptionOpen) flags |= ImGuiWindowFlags_AlwaysAutoResize;
    if (!ImGui::Begin("Lesson caption", nullptr, flags)) {
        ImGui::End();
        return;
    }
    if (!app.view.presentMode) recordShownWindow(app, "Lesson caption");
    ImGui::PushFont(gPlan.font);
    const std::string heading = lessonHeading(s);
    ImGui::SetWindowFontScale(kHeadingScale);
    ImGui::TextUnformatted(heading.c_str());
    ImGui::SetWindowFontScale(1.0f);
    // Beside the heading where it fits (never cut at the bar's edge): the step number typed so
    // far, else the key to press next, else the keys (in present mode the method and t).
    std::string status = lessonBarStatus(app.view.presentMode, app.sim.world().settings.method,
                                         app.sim.world().time);
    const std::string hint = lessonHint(s);
    if (!s.digits.empty())
        status = "Go to step " + s.digits + " (Enter)";
    else if (!hint.empty())
        status = app.view.presentMode ? status + "   ·   " + hint : hint;
    const float headingRight = ImGui::GetItemRectMax().x;
    const float statusWidth = ImGui::CalcTextSize(("   " + status).c_str()).x;
    if (headingRight + ImGui::GetStyle().ItemSpacing.x + statusWidth <=
        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
        ImGui::SameLine();
        ImGui::TextColored(uiDimColor(), "   %s", status.c_str());
    }
    ImGui::PushTextWrapPos(0.0f);
    if (gCaptionOpen || !gPlan.captionCut) {
        ImGui::TextUnformatted(step->caption.c_str());
    } else {
        const std::string cut = gPlan.caption + " (more)"; // one item: hovered or clicked whole
        ImGui::TextUnformatted(cut.c_str());
        if (ImGui::IsItemClicked()) gCaptionOpen = true;
        wrappedTooltip(step->caption);
    }
    const std::string asked = s.revealed ? answeredText(*step) : askedText(*step);
    if (!asked.empty())
        ImGui::TextColored(s.revealed ? uiNoteColor() : uiQuestionColor(), "%s", asked.c_str());
    if (gCaptionOpen && ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
        !ImGui::IsAnyItemHovered())
        gCaptionOpen = false; // a click on the open bar folds it again
    ImGui::PopTextWrapPos();
    ImGui::PopFont();
    ImGui::End();
}
