// The screen-text contract's reader (app/gui/ui/screen_text.h): text drawn with ImGui, read back
// from the draw data, with its rectangle, size, window and clipping. ImGui's own default font (no
// file needed); no GL: only the draw data is looked at.
#include "screen_text.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

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
