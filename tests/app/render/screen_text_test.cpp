// The screen-text contract's reader (app/gui/ui/widgets/screen_text.h): text drawn with ImGui, read
// back from the draw data, with its rectangle, size, window and clipping. ImGui's own default font
// (no file needed); no GL: only the draw data is looked at.
#include "screen_text.h"
#include "whole_rows.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

// One frame with ImGui's default font (13 px), `draw` between NewFrame and Render.
template <typename Draw> std::vector<ScreenText> textsOf(Draw draw) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(800, 600);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->AddFontDefault();
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(1)));
    ImGui::NewFrame();
    draw();
    ImGui::Render();
    std::vector<ScreenText> texts = readScreenText(*ImGui::GetDrawData(), *io.Fonts);
    ImGui::DestroyContext();
    forgetTextRoles();
    return texts;
}

const ScreenText* find(const std::vector<ScreenText>& texts, const std::string& text) {
    for (const ScreenText& t : texts)
        if (t.text == text) return &t;
    return nullptr;
}

TEST(TextJson, ReadsBackTextDrawnInTheSceneWithItsPlaceAndSize) {
    float width = 0.0f; // as ImGui measures it (before its rounding up)
    const auto texts = textsOf([&width] {
        ImDrawList* dl = ImGui::GetBackgroundDrawList();
        width = ImGui::GetFont()->CalcTextSizeA(13.0f, 1e9f, 0.0f, "m1 = 1 kg").x;
        dl->AddText(ImVec2(100, 50), IM_COL32_WHITE, "m1 = 1 kg");
        dl->AddText(ImGui::GetFont(), 26.0f, ImVec2(300, 200), IM_COL32_WHITE, "v = 6 m/s");
    });
    ASSERT_EQ(texts.size(), 2u);
    const ScreenText* label = find(texts, "m1 = 1 kg");
    ASSERT_TRUE(label);
    EXPECT_EQ(label->window, "scene");
    EXPECT_EQ(label->px, 13.0);
    EXPECT_EQ(label->rect.x, 100.0);
    EXPECT_EQ(label->rect.y, 50.0);
    EXPECT_EQ(label->rect.height, 13.0);
    EXPECT_NEAR(label->rect.width, width, 0.01); // the pen's advance over the text
    EXPECT_FALSE(label->clipped);
    const ScreenText* value = find(texts, "v = 6 m/s");
    ASSERT_TRUE(value);
    EXPECT_EQ(value->px, 26.0); // the size drawn at, not the font's baked size
    EXPECT_EQ(value->rect.height, 26.0);
}

TEST(TextJson, JoinsWrappedLinesAndListsAShadowOnce) {
    const auto texts = textsOf([] {
        ImDrawList* dl = ImGui::GetBackgroundDrawList();
        dl->AddText(ImVec2(11, 11), IM_COL32_BLACK, "red");
        dl->AddText(ImVec2(10, 10), IM_COL32_WHITE, "red"); // its shadow first, as the labels do
        dl->AddText(ImVec2(10, 100), IM_COL32_WHITE, "first line\nsecond line");
    });
    ASSERT_EQ(texts.size(), 2u);
    EXPECT_EQ(texts[0].text, "red");
    EXPECT_EQ(texts[0].rect.x, 10.0);
    EXPECT_EQ(texts[1].text, "first line\nsecond line");
    EXPECT_EQ(texts[1].rect.height, 26.0);
}

TEST(TextJson, NamesTheWindowAndSaysWhatItsEdgeCuts) {
    const auto texts = textsOf([] {
        ImGui::SetNextWindowPos(ImVec2(400, 300));
        ImGui::SetNextWindowSize(ImVec2(120, 80));
        ImGui::Begin("Collision inspector");
        ImGui::TextUnformatted("fits");
        ImGui::TextUnformatted("1000000 * 0.99999354 = 999993.54 kg m/s");
        ImGui::End();
        const TextRole role(ImGui::GetBackgroundDrawList(), "status");
        ImGui::GetBackgroundDrawList()->AddText(ImVec2(5, 5), IM_COL32_WHITE, "PAUSED");
    });
    const ScreenText* fits = find(texts, "fits");
    ASSERT_TRUE(fits);
    EXPECT_EQ(fits->window, "Collision inspector");
    EXPECT_FALSE(fits->clipped);
    bool cut = false; // the long line: what shows of it, cut at the window's edge
    for (const ScreenText& t : texts)
        if (t.text.rfind("1000000", 0) == 0) cut = t.clipped && t.text.size() < 38;
    EXPECT_TRUE(cut);
    const ScreenText* status = find(texts, "PAUSED");
    ASSERT_TRUE(status);
    EXPECT_EQ(status->window, "status");
}

// A text wholly outside its window's clip rectangle has no pixel drawn: it is not listed (ImGui
// still emits the glyphs of a line that starts exactly at the window's bottom edge).
TEST(TextJson, ListsNoTextWithNoPixelDrawn) {
    const auto texts = textsOf([] {
        ImGui::SetNextWindowPos(ImVec2(100, 100));
        ImGui::SetNextWindowSize(ImVec2(300, 200));
        ImGui::Begin("Controls");
        ImGui::TextUnformatted("shown");
        ImGui::GetWindowDrawList()->AddText(ImVec2(120, 400), IM_COL32_WHITE, "under the edge");
        ImGui::End();
    });
    EXPECT_TRUE(find(texts, "shown"));
    EXPECT_FALSE(find(texts, "under the edge"));
}

// A scroll region showing whole rows (WholeRows): the row its bottom edge cuts is hidden, not
// cut; so is the row its top edge cuts when it is scrolled. The rows here are 13 px lines 4 px
// apart (ImGui's default font and spacing): 17 px a row, in a child 60 px high.
TEST(WholeRows, HidesTheRowsItsEdgesWouldCut) {
    for (const float scroll : {0.0f, 8.0f}) {
        const auto texts = textsOf([scroll] {
            ImGui::SetNextWindowPos(ImVec2(0, 0));
            ImGui::SetNextWindowSize(ImVec2(300, 300));
            ImGui::Begin("Controls");
            ImGui::BeginChild("##rows", ImVec2(0.0f, 60.0f));
            WholeRows whole;
            ImGui::SetCursorPosY(-scroll); // the content `scroll` px up, as if scrolled
            for (int i = 0; i < 10; ++i) ImGui::Text("row %d", i);
            whole.end();
            ImGui::EndChild();
            ImGui::End();
        });
        int listed = 0;
        for (const ScreenText& t : texts) {
            EXPECT_FALSE(t.clipped) << t.text << " at scroll " << scroll;
            listed += t.text.rfind("row ", 0) == 0 ? 1 : 0;
        }
        // Scroll 0: rows 0 to 2 whole (0 to 47 px), row 3 (51 to 64) cut: hidden. Scroll 8: row
        // 0 (-8 to 5) cut at the top, rows 1 to 3 whole (9 to 56), row 4 (60 to 73) hidden.
        EXPECT_EQ(listed, 3) << "at scroll " << scroll;
        EXPECT_TRUE(find(texts, scroll == 0.0f ? "row 0" : "row 1"));
        EXPECT_FALSE(find(texts, scroll == 0.0f ? "row 3" : "row 0"));
    }
}

// WholeRows::rowsOf merges the spans drawn one after another that meet before it sorts them: its
// rows are exactly those of sorting every span and merging (the rule before), on random spans
// on a quarter-pixel grid (so that many touch exactly, half a pixel apart or end to end), some
// tall, in random order and in runs as a line of text draws them.
TEST(WholeRows, RowsAreThoseOfSortingEverySpan) {
    const auto reference = [](std::vector<imgui_ext::Span> spans, float tall) {
        spans.erase(
            std::remove_if(spans.begin(), spans.end(),
                           [tall](const imgui_ext::Span& s) { return s.y1 - s.y0 >= tall; }),
            spans.end());
        std::stable_sort(
            spans.begin(), spans.end(),
            [](const imgui_ext::Span& a, const imgui_ext::Span& b) { return a.y0 < b.y0; });
        std::vector<imgui_ext::Span> rows;
        for (const imgui_ext::Span& s : spans) {
            if (!rows.empty() && s.y0 <= rows.back().y1 + 0.5f)
                rows.back().y1 = std::max(rows.back().y1, s.y1);
            else
                rows.push_back(s);
        }
        return rows;
    };
    std::mt19937 random(42);
    int merged = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::uniform_int_distribution<int> count(0, 60), quarter(-40, 800), height(0, 80);
        std::vector<imgui_ext::Span> spans;
        const int n = count(random);
        while (static_cast<int>(spans.size()) < n) {
            const float y0 = 0.25f * static_cast<float>(quarter(random));
            const float h =
                0.25f * static_cast<float>(height(random)) * (trial % 5 == 0 ? 8.0f : 1.0f);
            // A run of triangles near one height (a line of text), or a lone one.
            const int run = 1 + static_cast<int>(random() % 6);
            for (int k = 0; k < run; ++k)
                spans.push_back({y0 + 0.25f * static_cast<float>(random() % 5),
                                 y0 + h - 0.25f * static_cast<float>(random() % 3)});
        }
        for (imgui_ext::Span& s : spans) s.y1 = std::max(s.y1, s.y0);
        const float tall = trial % 3 == 0 ? 1e9f : 0.25f * static_cast<float>(40 + trial % 200);
        const std::vector<imgui_ext::Span> want = reference(spans, tall);
        const std::vector<imgui_ext::Span> got = WholeRows::rowsOf(spans, tall);
        ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
        for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].y0, want[i].y0) << "trial " << trial << " row " << i;
            EXPECT_EQ(got[i].y1, want[i].y1) << "trial " << trial << " row " << i;
        }
        merged += want.size() < spans.size() ? 1 : 0;
    }
    EXPECT_GT(merged, 1000); // the spans did merge into rows, most trials
}

TEST(TextJson, IsTheDocumentedJson) {
    ScreenText t;
    t.text = "say \"hi\"\n";
    t.rect = {1, 2, 30.5, 13};
    t.px = 13;
    t.window = "caption";
    const nlohmann::json j = nlohmann::json::parse(screenTextJson({t}));
    ASSERT_EQ(j.at("texts").size(), 1u);
    const nlohmann::json& e = j.at("texts").at(0);
    EXPECT_EQ(e.at("text"), "say \"hi\"\n");
    EXPECT_EQ(e.at("rect"), nlohmann::json::parse("[1, 2, 30.5, 13]"));
    EXPECT_EQ(e.at("px"), 13);
    EXPECT_EQ(e.at("window"), "caption");
    EXPECT_EQ(e.at("clipped"), false);
    EXPECT_EQ(screenTextJson({}), "{\"texts\": []}\n");
}

} // namespace
