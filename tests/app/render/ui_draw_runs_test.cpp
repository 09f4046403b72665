// The UI renderer's split of an ImGui draw command into solid and textured runs (no GL).
#include "ui_draw_runs.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

const ImVec2 kWhite{0.25f, 0.75f}; // the atlas's white texel in these tests

// A triangle list built quad by quad (two triangles each), solid or textured.
struct Mesh {
    std::vector<ImDrawVert> vertices;
    std::vector<ImDrawIdx> indices;

    void quad(float x, float y, float size, bool solid) {
        const ImVec2 uv = solid ? kWhite : ImVec2(0.5f, 0.5f);
        const auto base = static_cast<ImDrawIdx>(vertices.size());
        const ImVec2 corners[4] = {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
        for (const ImVec2& c : corners) vertices.push_back({c, uv, 0xFFFFFFFFu});
        for (int k : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<ImDrawIdx>(base + k));
    }
    std::vector<UiDrawRun> runs(float minSolidPixels, unsigned indexBase = 0) const {
        std::vector<UiDrawRun> out;
        splitIntoRuns(vertices.data(), indices.data(), indexBase,
                      static_cast<unsigned>(indices.size()), kWhite, minSolidPixels, out);
        return out;
    }
};

} // namespace

TEST(UiDrawRuns, SplitsSolidAndTexturedInDrawingOrder) {
    Mesh m;
    m.quad(0, 0, 100, true);  // a window background: 10,000 px
    m.quad(10, 10, 8, false); // a glyph
    m.quad(10, 30, 8, false); // a glyph
    m.quad(0, 50, 100, true); // a frame
    const std::vector<UiDrawRun> runs = m.runs(0.0f, 30);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_TRUE(runs[0].solid);
    EXPECT_EQ(runs[0].firstIndex, 30u); // counted from the command's first index
    EXPECT_EQ(runs[0].indexCount, 6u);
    EXPECT_FALSE(runs[1].solid);
    EXPECT_EQ(runs[1].firstIndex, 36u);
    EXPECT_EQ(runs[1].indexCount, 12u);
    EXPECT_TRUE(runs[2].solid);
    EXPECT_EQ(runs[2].firstIndex, 48u);
    EXPECT_EQ(runs[2].indexCount, 6u);
}

TEST(UiDrawRuns, SmallSolidRunsJoinTheTexturedOnesAroundThem) {
    // A checkbox's 16 x 16 frame (256 px) between two labels: drawing it textured looks the
    // same and saves two draw calls; the 10,000 px background stays solid.
    Mesh m;
    m.quad(0, 0, 100, true);
    m.quad(10, 10, 8, false);
    m.quad(30, 10, 16, true);
    m.quad(50, 10, 8, false);
    const std::vector<UiDrawRun> runs = m.runs(1000.0f);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_TRUE(runs[0].solid);
    EXPECT_EQ(runs[0].indexCount, 6u);
    EXPECT_FALSE(runs[1].solid);
    EXPECT_EQ(runs[1].firstIndex, 6u);
    EXPECT_EQ(runs[1].indexCount, 18u);
}

TEST(UiDrawRuns, AOneRunCommandStaysAsItIs) {
    Mesh m;
    m.quad(0, 0, 4, true); // 16 px, under any threshold, but drawing it textured saves nothing
    const std::vector<UiDrawRun> runs = m.runs(1000.0f);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_TRUE(runs[0].solid);
}

TEST(UiDrawRuns, ATriangleWithOneTexturedVertexIsTextured) {
    // ImGui's anti-aliased lines sample the atlas at some vertices only.
    Mesh m;
    m.quad(0, 0, 100, true);
    m.vertices[2].uv = ImVec2(0.5f, 0.5f); // shared by both triangles of the quad
    const std::vector<UiDrawRun> runs = m.runs(0.0f);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_FALSE(runs[0].solid);
    EXPECT_EQ(runs[0].indexCount, 6u);
}

TEST(UiDrawRuns, AppendsAfterWhatIsAlreadyThere) {
    Mesh m;
    m.quad(0, 0, 100, true);
    std::vector<UiDrawRun> runs{{0, 3, false}};
    splitIntoRuns(m.vertices.data(), m.indices.data(), 0, 6, kWhite, 0.0f, runs);
    ASSERT_EQ(runs.size(), 2u); // not merged with a run of another command
    EXPECT_TRUE(runs[1].solid);
}
