// The lesson's caption bar: across the top of the screen, over the panel too (a slide's title
// area), "n / N · title" large with the status beside it (the key to press next, or the keys; in
// present mode the method and t: lessonBarStatus), the step's caption under it, then the question
// ("Predict: ...", with its choices lettered A-D, at the setup and while the step plays; its answer
// at the moment, or why there is none). The one caption of a lesson, presenting or not. Opaque.
// What it says is computed from the world as it is (lessonTexts, lesson_prompt.h): true after any
// change of the lecturer's; wrapped at spaces and never inside an equation's number (wrapFormula).
//
// Its height is planned for a step on a screen (planBar), not measured every frame: the most of
// what the setup and the moment need (the answer as written included), so the scene below keeps
// one size while the step is asked, played and answered, and at most kMaxCaptionShare of the
// screen's height: the question or answer is always whole, the caption shows the lines that fit
// ("... (more)", the whole on hovering it or a click), and where even that does not fit half the
// padding is tried, then a smaller font. The plan's height is app.view.captionHeight, which the
// layout keeps free above the panel, the windows and the scene. In present mode the bar is the
// scene's caption, not a window: --layout-json lists no window there.
#include "app_frame.h"
#include "lesson_prompt.h"
#include "overlay_window.h"
#include "text_format.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

// The heading's size relative to the bar's font.
constexpr float kHeadingScale = 1.25f;

// A text of the bar under its heading: wrapped at the bar's width (wrapFormula); `beside`: on the
// previous text's row where that row is one line and it fits there whole (a choice after a short
// question, or after another choice).
struct Piece {
    std::string text;
    ImVec4 color;
    bool beside = false;
};
// A piece as laid out: its lines, and where it starts from the first piece's top left.
struct Placed {
    std::string lines;
    ImVec4 color;
    ImVec2 at;
};

double measured(const std::string& line) {
    return static_cast<double>(ImGui::CalcTextSize(line.c_str()).x);
}

// The widest line of `lines`, px.
float widest(const std::string& lines) {
    float most = 0.0f;
    std::size_t start = 0;
    while (start <= lines.size()) {
        const std::size_t end = std::min(lines.find('\n', start), lines.size());
        most = std::max(most, static_cast<float>(measured(lines.substr(start, end - start))));
        start = end + 1;
    }
    return most;
}

// The pieces laid out `width` px wide in the current font, rows ItemSpacing.y apart as ImGui
// stacks items: their places into `out` (may be null), and the height they take.
float flow(const std::vector<Piece>& pieces, float width, std::vector<Placed>* out) {
    const float line = ImGui::GetTextLineHeight();
    const float gapY = ImGui::GetStyle().ItemSpacing.y, gapX = ImGui::CalcTextSize("    ").x;
    float rowTop = 0.0f, rowBottom = 0.0f, right = 0.0f;
    bool first = true;
    for (const Piece& p : pieces) {
        if (p.text.empty()) continue;
        const float width1 = static_cast<float>(measured(p.text));
        Placed placed{p.text, p.color, ImVec2(0.0f, 0.0f)};
        // Beside a one-line row only: after a wrapped question it would sit at its first line's
        // end, in the middle of the sentence.
        const bool oneLine = rowBottom - rowTop <= line + 0.5f;
        if (!first && p.beside && oneLine && p.text.find('\n') == std::string::npos &&
            right + gapX + width1 <= width) {
            placed.at = ImVec2(right + gapX, rowTop);
            right += gapX + width1;
            rowBottom = std::max(rowBottom, rowTop + line);
        } else {
            rowTop = first ? 0.0f : rowBottom + gapY;
            placed.lines = wrapFormula(p.text, width, measured);
            placed.at = ImVec2(0.0f, rowTop);
            right = widest(placed.lines);
            const auto lines = std::count(placed.lines.begin(), placed.lines.end(), '\n') + 1;
            rowBottom = rowTop + static_cast<float>(lines) * line;
        }
        first = false;
        if (out) out->push_back(std::move(placed));
    }
    return rowBottom;
}

// What the bar says under the caption: the question and its choices, the answer, or why there is
// none.
std::vector<Piece> askedPieces(const LessonTexts& t, bool revealed) {
    if (!t.missed.empty()) return {{"No answer: " + t.missed, uiNoteColor()}};
    if (revealed) return {{"Answer: " + t.answer, uiNoteColor()}};
    if (t.question.empty()) return {};
    std::vector<Piece> out{{"Predict: " + t.question, uiQuestionColor()}};
    for (const std::string& choice : t.choices) out.push_back({choice, uiQuestionColor(), true});
    return out;
}

// What the bar shows of a step on a screen, and how high it is: planned when the step, what it
// says, the screen or the fonts change (planBar), not every frame.
struct BarPlan {
    std::string key; // what it was planned for
    ImFont* font = nullptr;
    std::string caption; // the step's caption as shown: whole, or the lines that fit and "..."
    bool captionCut = false;
    bool tight = false;  // half the padding and spacing (pushTight): the last resort
    float height = 0.0f; // px: the most the setup's and the moment's texts take
};
BarPlan gPlan;
bool gCaptionOpen = false; // "(more)" clicked: the whole caption, over the scene

constexpr const char* kMore = " (more)";

// The bar's padding and the spacing between its rows halved, when `tight`.
void pushTight(bool tight) {
    if (!tight) return;
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding,
                        ImVec2(style.WindowPadding.x, 0.5f * style.WindowPadding.y));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing,
                        ImVec2(style.ItemSpacing.x, 0.5f * style.ItemSpacing.y));
}
void popTight(bool tight) {
    if (tight) ImGui::PopStyleVar(2);
}

// The first words of `text` that take at most `lines` lines `width` px wide, followed by "..."
// (unless they end a sentence) and kMore ("" when not even a word fits).
std::string firstLines(const std::string& text, float width, int lines) {
    const float most = static_cast<float>(lines) * ImGui::GetTextLineHeight() + 0.5f;
    std::string best;
    std::size_t end = 0;
    while (end != std::string::npos) {
        end = text.find_first_of(" \n", end + 1);
        std::string tried = text.substr(0, end);
        if (tried.back() != '.') tried += "..."; // a whole sentence ends as it is

        if (flow({{tried + kMore, ImVec4()}}, width, nullptr) > most) break;
        best = tried;
    }
    return best;
}

// The heading "n / N · title" as drawn kHeadingScale times the current font, wrapped `width` px
// wide (a long title on a narrow screen takes two lines rather than being cut).
std::string headingLines(const std::string& heading, float width) {
    return wrapFormula(heading, width / kHeadingScale, measured);
}

// The step's texts at its setup and at its moment, whichever the bar shows now, and the answer as
// written: the bar is planned for the tallest.
struct StepTexts {
    std::string heading;
    LessonTexts now;
    std::string answerAsWritten, missedAsWritten;
};

StepTexts stepTexts(const App& app) {
    const LessonSession& s = app.lesson;
    StepTexts t{lessonHeading(s), lessonTexts(s, app.sim), "", ""};
    if (s.written) {
        const StepAnswer a = stepAnswer(*s.step(), *s.written, {}, nullptr);
        t.answerAsWritten = a.text;
        t.missedAsWritten = a.missed;
    }
    return t;
}

std::string planKey(const LessonSession& s, const StepTexts& t, float width, float height,
                    float uiScale) {
    std::string key =
        std::to_string(s.current) + "|" + std::to_string(width) + "x" + std::to_string(height) +
        "|" + std::to_string(static_cast<double>(uiCaptionFont()->FontSize)) + "|" +
        std::to_string(static_cast<double>(uiScale)) + "|" + s.lesson->name + "|" + t.heading +
        "|" + t.now.caption + "|" + t.now.question + "|" + t.now.answer + "|" + t.now.missed;
    for (const std::string& c : t.now.choices) key += "|" + c;
    return key;
}

// The bar for the open step on a `width` x `screenHeight` screen, in the first font and padding
// (the slide-sized caption font, then with half the padding, then the UI's font, then the compact
// one, then with half the padding) in which it fits within kMaxCaptionShare of the height.
BarPlan planBar(const StepTexts& t, const std::string& key, float width, float screenHeight) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = width - 2.0f * style.WindowPadding.x;
    const float most = static_cast<float>(kMaxCaptionShare) * screenHeight;
    // Every state the bar shows: the question, the answer now and as written, the missed event.
    LessonTexts asked = t.now, answered = t.now, answeredAsWritten = t.now, missed = t.now;
    asked.missed.clear();
    answered.missed.clear();
    answeredAsWritten.missed.clear();
    answeredAsWritten.answer = t.answerAsWritten;
    missed.missed = !t.now.missed.empty() ? t.now.missed : t.missedAsWritten;
    BarPlan plan;
    plan.key = key;
    const struct {
        ImFont* font;
        bool tight;
    } tries[] = {{uiCaptionFont(), false},
                 {uiCaptionFont(), true},
                 {ImGui::GetFont(), false},
                 {uiCompactFont(), false},
                 {uiCompactFont(), true}};
    for (const auto& tried : tries) {
        ImGui::PushFont(tried.font);
        pushTight(tried.tight);
        const float line = ImGui::GetTextLineHeight(), gap = style.ItemSpacing.y;
        float askedHeight = flow(askedPieces(asked, false), wrap, nullptr);
        if (!t.now.question.empty()) {
            askedHeight = std::max({askedHeight, flow(askedPieces(answered, true), wrap, nullptr),
                                    flow(askedPieces(answeredAsWritten, true), wrap, nullptr)});
        }
        if (!missed.missed.empty())
            askedHeight = std::max(askedHeight, flow(askedPieces(missed, true), wrap, nullptr));
        const std::string heading = headingLines(t.heading, wrap);
        const auto headingRows = std::count(heading.begin(), heading.end(), '\n') + 1;
        const float fixed = 2.0f * style.WindowPadding.y +
                            static_cast<float>(headingRows) * line * kHeadingScale +
                            (askedHeight > 0.0f ? gap + askedHeight : 0.0f);
        const float caption = flow({{t.now.caption, ImVec4()}}, wrap, nullptr);
        plan.font = tried.font;
        plan.tight = tried.tight;
        plan.caption = t.now.caption;
        plan.captionCut = false;
        plan.height = fixed + (caption > 0.0f ? gap + caption : 0.0f);
        const int room = static_cast<int>(std::floor((most - fixed - gap) / line));
        if (plan.height > most) { // the caption's first lines, "... (more)", or "... (more)"
            plan.caption = room >= 1 ? firstLines(t.now.caption, wrap, room) : "";
            if (plan.caption.empty()) plan.caption = "...";
            plan.captionCut = true;
            plan.height = fixed + gap + flow({{plan.caption + kMore, ImVec4()}}, wrap, nullptr);
        }
        popTight(tried.tight);
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
    const StepTexts texts = stepTexts(app);
    const std::string key = planKey(s, texts, io.DisplaySize.x, io.DisplaySize.y, app.view.uiScale);
    if (key != gPlan.key) {
        const bool sameStep =
            gPlan.key.substr(0, gPlan.key.find('|')) == key.substr(0, key.find('|'));
        gPlan = planBar(texts, key, io.DisplaySize.x, io.DisplaySize.y);
        if (!sameStep) gCaptionOpen = false;
    }
    app.view.captionHeight = gPlan.height;
}

void drawLessonCaption(App& app) {
    const LessonSession& s = app.lesson;
    const LessonStep* step = s.step();
    if (!step || gPlan.font == nullptr) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    // The planned height; the whole caption ("(more)" clicked) grows it over the scene. On a
    // touch screen it keeps the planned height and scrolls (a swipe): grown, it covered the
    // status line under it and went past a third of a phone's height.
    const bool grown = gCaptionOpen && !app.ui.touchUi;
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, grown ? 0.0f : gPlan.height),
                             ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (grown) flags |= ImGuiWindowFlags_AlwaysAutoResize;
    pushTight(gPlan.tight);
    if (!ImGui::Begin("Lesson caption", nullptr, flags)) {
        ImGui::End();
        popTight(gPlan.tight);
        return;
    }
    if (!app.view.presentMode) recordShownWindow(app, "Lesson caption");
    ImGui::PushFont(gPlan.font);
    const std::string heading = headingLines(lessonHeading(s), ImGui::GetContentRegionAvail().x);
    ImGui::SetWindowFontScale(kHeadingScale);
    ImGui::TextUnformatted(heading.c_str(), heading.c_str() + heading.size());
    ImGui::SetWindowFontScale(1.0f);
    // Beside the heading where it fits (never cut at the bar's edge): the step number typed so
    // far, else the key to press next and the keys, else the key to press next alone.
    const std::string keys = lessonBarStatus(app.view.presentMode, app.sim.world().settings.method,
                                             app.sim.world().time, app.ui.touchUi);
    const std::string hint = lessonHint(s, app.ui.touchUi);
    std::vector<std::string> statuses;
    if (!s.digits.empty()) {
        statuses.push_back("Go to step " + s.digits + " (Enter)");
    } else if (!hint.empty() && keys.empty()) {
        statuses.push_back(hint);
    } else if (!hint.empty()) {
        statuses.push_back(hint + "   \xc2\xb7   " +
                           lessonBarStatus(app.view.presentMode, app.sim.world().settings.method,
                                           app.sim.world().time, app.ui.touchUi, true));
        statuses.push_back(hint);
    } else {
        statuses.push_back(keys);
    }
    const float headingRight = ImGui::GetItemRectMax().x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (const std::string& status : statuses) {
        const std::string shown = "   " + status;
        if (headingRight + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(shown.c_str()).x >
            right)
            continue;
        ImGui::SameLine();
        if (app.view.presentMode)
            ImGui::TextUnformatted(shown.c_str());
        else
            ImGui::TextColored(uiDimColor(), "%s", shown.c_str());
        break;
    }
    // The caption (whole, or its first lines and "(more)"), then the question and its choices,
    // the answer, or why there is none: laid out as planned (flow).
    const LessonTexts texts = lessonTexts(s, app.sim);
    const bool cut = gPlan.captionCut && !gCaptionOpen;
    std::vector<Piece> pieces{
        {cut ? gPlan.caption + kMore : texts.caption, ImGui::GetStyleColorVec4(ImGuiCol_Text)}};
    const std::vector<Piece> asked = askedPieces(texts, s.revealed);
    pieces.insert(pieces.end(), asked.begin(), asked.end());
    std::vector<Placed> placed;
    const float wrap = ImGui::GetContentRegionAvail().x;
    flow(pieces, wrap, &placed);
    const ImVec2 origin = ImGui::GetCursorPos();
    // Open before this frame: the click that opens it is not also the click that folds it.
    const bool wasOpen = gCaptionOpen;
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const Placed& p = placed[i];
        ImGui::SetCursorPos(ImVec2(origin.x + p.at.x, origin.y + p.at.y));
        ImGui::PushStyleColor(ImGuiCol_Text, p.color);
        ImGui::TextUnformatted(p.lines.c_str(), p.lines.c_str() + p.lines.size());
        ImGui::PopStyleColor();
        if (i == 0 && cut) { // the caption's first lines: hovered, the whole; clicked, opened
            if (ImGui::IsItemClicked()) gCaptionOpen = true;
            wrappedTooltip(texts.caption);
        }
    }
    if (wasOpen && ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
        !ImGui::IsAnyItemHovered())
        gCaptionOpen = false; // a click on the open bar folds it again
    ImGui::PopFont();
    ImGui::End();
    popTight(gPlan.tight);
}
