// The class poll on the projector (docs/poll.md): while the vote is open, the QR code of the
// poll's URL, the short URL and how many phones joined and voted (never the counts); at the
// moment, the counts of each choice with their letters and percentages, every round side by
// side, the choice the run proved marked by a check, the words "proved by the run" and a frame
// (not by colour alone). In the classroom's text size (uiCaptionFont). Over the scene's right
// edge, under the lesson's caption bar. And the panel's "Class poll" section: the addresses,
// the button (the browser build says why there is none).
#include "app_frame.h"
#include "class_poll.h"
#include "lesson.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace {

// The QR code on a white plate with its quiet zone (4 modules), `module` px per module.
void drawQr(const PollScreen& s, float module) {
    const float quiet = 4.0f * module;
    const float side = static_cast<float>(s.qrSize) * module + 2.0f * quiet;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddRectFilled(at, ImVec2(at.x + side, at.y + side), IM_COL32(255, 255, 255, 255));
    for (int y = 0; y < s.qrSize; ++y)
        for (int x = 0; x < s.qrSize; ++x) {
            if (!s.qrDark[static_cast<std::size_t>(y * s.qrSize + x)]) continue;
            const ImVec2 a(at.x + quiet + static_cast<float>(x) * module,
                           at.y + quiet + static_cast<float>(y) * module);
            list->AddRectFilled(a, ImVec2(a.x + module, a.y + module), IM_COL32(0, 0, 0, 255));
        }
    ImGui::Dummy(ImVec2(side, side));
}

std::string percent(int count, int total) {
    if (total == 0) return "-";
    return std::to_string(static_cast<int>(std::lround(100.0 * count / total))) + "%";
}

// One row per choice: its letter, then a bar per round with "count (percent)"; the proved
// choice framed and said.
void drawHistogram(const PollScreen& s, float width) {
    const std::size_t rounds = s.rounds.size();
    if (rounds > 1) {
        std::string legend;
        for (std::size_t r = 0; r < rounds; ++r)
            legend += (r ? "   " : "") + std::string("vote ") + std::to_string(r + 1) + ": " +
                      (r == 0   ? "upper"
                       : r == 1 ? "lower"
                                : "next") +
                      " bar";
        ImGui::PushStyleColor(ImGuiCol_Text, uiDimColor());
        ImGui::TextUnformatted(legend.c_str());
        ImGui::PopStyleColor();
    }
    std::vector<int> totals;
    for (const std::vector<int>& counts : s.rounds) {
        int total = 0;
        for (int c : counts) total += c;
        totals.push_back(total);
    }
    const float line = ImGui::GetTextLineHeight();
    const float letterWidth = ImGui::CalcTextSize("W").x * 1.4f;
    const float labelWidth = ImGui::CalcTextSize("000 (100%)").x;
    const float barMax = std::max(line, width - letterWidth - labelWidth - 3.0f * line * 0.3f);
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 barColors[2] = {uiThemed(IM_COL32(120, 170, 255, 255)),
                                uiThemed(IM_COL32(255, 190, 90, 255))};
    const float left = ImGui::GetCursorPosX();
    for (std::size_t c = 0; c < s.choices.size(); ++c) {
        const bool proved = static_cast<int>(c) == s.proved;
        const ImVec2 top = ImGui::GetCursorScreenPos();
        ImGui::TextUnformatted(choiceLetter(c).c_str());
        for (std::size_t r = 0; r < rounds; ++r) {
            const int count = c < s.rounds[r].size() ? s.rounds[r][c] : 0;
            if (r == 0)
                ImGui::SameLine(left + letterWidth);
            else
                ImGui::SetCursorPosX(left + letterWidth); // the next round's bar under it
            const ImVec2 at = ImGui::GetCursorScreenPos();
            const float share = totals[r] ? static_cast<float>(count) / totals[r] : 0.0f;
            const float barWidth = std::max(2.0f, share * barMax);
            list->AddRectFilled(ImVec2(at.x, at.y + line * 0.12f),
                                ImVec2(at.x + barWidth, at.y + line * 0.88f), barColors[r % 2]);
            ImGui::Dummy(ImVec2(barWidth + line * 0.3f, line));
            ImGui::SameLine();
            const std::string label =
                std::to_string(count) + " (" + percent(count, totals[r]) + ")";
            ImGui::TextUnformatted(label.c_str());
        }
        if (proved) {
            // A check mark drawn (the font may have no glyph for it), then the words.
            ImGui::SetCursorPosX(left + letterWidth);
            const ImVec2 at = ImGui::GetCursorScreenPos();
            const ImVec2 tick[3] = {ImVec2(at.x + line * 0.1f, at.y + line * 0.55f),
                                    ImVec2(at.x + line * 0.35f, at.y + line * 0.8f),
                                    ImVec2(at.x + line * 0.85f, at.y + line * 0.2f)};
            list->AddPolyline(tick, 3, text, 0, std::max(2.0f, line * 0.12f));
            ImGui::Dummy(ImVec2(line, line));
            ImGui::SameLine();
            ImGui::TextUnformatted("proved by the run");
            const ImVec2 bottom = ImGui::GetItemRectMax();
            list->AddRect(ImVec2(top.x - line * 0.2f, top.y - line * 0.1f),
                          ImVec2(top.x + width, bottom.y + line * 0.1f), text, line * 0.15f, 0,
                          std::max(2.0f, line * 0.08f));
        }
    }
    std::string voters = "Voters: ";
    for (std::size_t r = 0; r < rounds; ++r)
        voters += (r ? ", then " : "") + std::to_string(totals[r]);
    ImGui::TextUnformatted(voters.c_str());
}

} // namespace

void drawPollWindow(App& app) {
    if (!app.poll.on() || !app.lesson.active()) return;
    const PollScreen s = pollScreen(app.poll, app.lesson);
    const ImGuiIO& io = ImGui::GetIO();
    const ScreenRect& scene = app.view.layout.scene;
    const float height = io.DisplaySize.y;
    ImFont* font = uiCaptionFont(); // the classroom's size, whatever the UI scale
    const float line = font->FontSize;
    // QR modules of at least 3 px, about a third of the screen's height in all.
    const float module =
        std::max(3.0f, std::floor(height * 0.3f / static_cast<float>(s.qrSize + 8)));
    const float urlWidth = font->CalcTextSizeA(line, FLT_MAX, 0.0f, s.url.c_str()).x;
    const float width = std::max(static_cast<float>(s.qrSize + 8) * module, urlWidth) +
                        2.0f * ImGui::GetStyle().WindowPadding.x;
    const float histogramWidth = std::max(width, line * 16.0f);
    const float w = s.histogram ? histogramWidth : width;
    const float right = static_cast<float>(scene.x + scene.width);
    const float top = static_cast<float>(scene.y);
    ImGui::SetNextWindowPos(ImVec2(std::max(0.0f, right - w - line * 0.5f), top + line * 0.5f),
                            ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.97f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing;
    if (!ImGui::Begin("Class poll", nullptr, flags)) {
        ImGui::End();
        return;
    }
    recordShownWindow(app, "Class poll");
    ImGui::PushFont(font);
    if (!s.asking) {
        ImGui::TextUnformatted("Join the poll:");
        drawQr(s, module);
        ImGui::TextUnformatted(s.url.c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, uiDimColor());
        textWrappedAtSpaces(s.note.empty() ? "No question at this step." : "No vote: " + s.note);
        ImGui::PopStyleColor();
    } else if (s.open) {
        ImGui::TextUnformatted("Vote on your phone:");
        drawQr(s, module);
        ImGui::TextUnformatted(s.url.c_str());
        const std::string counts =
            std::to_string(s.joined) + " joined \xC2\xB7 " + std::to_string(s.voted) + " voted";
        ImGui::TextUnformatted(counts.c_str());
    } else if (s.histogram) {
        ImGui::TextUnformatted("The class voted:");
        drawHistogram(s, histogramWidth - 2.0f * ImGui::GetStyle().WindowPadding.x);
    } else {
        const std::string closed =
            "Vote closed: " + std::to_string(s.voted) + (s.voted == 1 ? " vote." : " votes.");
        ImGui::TextUnformatted(closed.c_str());
        ImGui::TextUnformatted("The counts show at the moment.");
    }
    ImGui::PopFont();
    // The lecturer's buttons, in the UI's size.
    if (s.asking && s.open) {
        if (ImGui::Button("Close vote")) closePollVote(app.poll);
    } else if (s.asking) {
        if (ImGui::Button("Vote again")) {
            applyAction(app, Action::Reset); // the step again from its setup
            pollVoteAgain(app.poll);
        }
    }
    if (s.asking) ImGui::SameLine();
    if (ImGui::Button("Stop poll")) stopPoll(app.poll);
    ImGui::End();
}

void pollSection(App& app) {
    if (!ImGui::CollapsingHeader("Class poll")) return;
    if (!pollAvailable()) {
        textWrappedAtSpaces(kPollUnavailable);
        return;
    }
    ClassPoll& poll = app.poll;
    if (poll.addresses.empty()) listPollAddresses(poll);
    if (!poll.on()) {
        const char* current = poll.addresses[poll.address].c_str();
        if (ImGui::BeginCombo("address", current)) {
            for (std::size_t i = 0; i < poll.addresses.size(); ++i)
                if (ImGui::Selectable(poll.addresses[i].c_str(), i == poll.address))
                    poll.address = i;
            ImGui::EndCombo();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The phones must reach it: the network they are on (the first is "
                              "the default route's)");
        if (!app.lesson.active()) {
            ImGui::PushStyleColor(ImGuiCol_Text, uiDimColor());
            textWrappedAtSpaces("Open a lesson: the poll asks its steps' questions.");
            ImGui::PopStyleColor();
        } else if (ImGui::Button("Poll the class (A)")) {
            applyAction(app, Action::TogglePoll);
        }
    } else {
        textWrappedAtSpaces(poll.session ? pollScreen(poll, app.lesson).url : "");
        if (ImGui::Button("Stop the poll (A)")) applyAction(app, Action::TogglePoll);
    }
    if (!poll.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, uiErrorColor());
        textWrappedAtSpaces(poll.error);
        ImGui::PopStyleColor();
    }
}
