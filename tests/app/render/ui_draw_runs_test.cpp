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
    std::vector<UiDrawRun> runs{{0, 3, false, {}, 0}};
    splitIntoRuns(m.vertices.data(), m.indices.data(), 0, 6, kWhite, 0.0f, runs);
    ASSERT_EQ(runs.size(), 2u); // not merged with a run of another command
    EXPECT_TRUE(runs[1].solid);
}

namespace {

// A convex fan of one colour (ImGui's filled shapes: triangles (v, v+k+1, v+k+2)).
void fan(Mesh& m, const std::vector<ImVec2>& corners, ImU32 color) {
    const auto base = static_cast<ImDrawIdx>(m.vertices.size());
    for (const ImVec2& c : corners) m.vertices.push_back({c, kWhite, color});
    for (std::size_t k = 0; k + 2 < corners.size(); ++k)
        for (std::size_t i : {std::size_t{0}, k + 1, k + 2})
            m.indices.push_back(static_cast<ImDrawIdx>(base + i));
}

std::vector<UiDrawRun> fills(const Mesh& m, int minPixels, ImVec2 scale = ImVec2(1, 1)) {
    std::vector<UiDrawRun> runs = m.runs(0.0f, 12);
    findOpaqueFills(m.vertices.data(), m.indices.data(), 12, ImVec2(0, 0), scale, minPixels, runs);
    return runs;
}

} // namespace

TEST(UiDrawRuns, AnOpaqueFillKnowsThePixelsItSurelyCovers) {
    // A glyph, then a window's background from (10.3, 20) to (110.3, 120): the pixels whose
    // centres lie inside it, columns 10 to 109 and rows 20 to 119.
    Mesh m;
    m.quad(0, 0, 8, false);
    fan(m, {{10.3f, 20}, {110.3f, 20}, {110.3f, 120}, {10.3f, 120}}, IM_COL32(30, 29, 36, 255));
    const std::vector<UiDrawRun> runs = fills(m, 1000);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_FALSE(runs[0].solid);
    EXPECT_TRUE(runs[1].solid);
    EXPECT_EQ(runs[1].firstIndex, 18u);
    EXPECT_EQ(runs[1].indexCount, 6u);
    EXPECT_EQ(runs[1].color, IM_COL32(30, 29, 36, 255));
    EXPECT_EQ(runs[1].inside.x0, 10);
    EXPECT_EQ(runs[1].inside.x1, 110);
    EXPECT_EQ(runs[1].inside.y0, 20);
    EXPECT_EQ(runs[1].inside.y1, 120);
    // At a framebuffer scale of 2: twice the pixels.
    const std::vector<UiDrawRun> twice = fills(m, 1000, ImVec2(2, 2));
    EXPECT_EQ(twice[1].inside.x0, 21);
    EXPECT_EQ(twice[1].inside.y1, 240);
}

TEST(UiDrawRuns, ARoundedFillLosesItsCornersRows) {
    // Corners cut 9 px deep (a rounded window's arcs, coarsely): only the rows between the
    // cuts are surely covered across the whole width. The fill sits between two others.
    Mesh m;
    m.quad(0, 0, 20, true); // 400 px: too few to clear
    fan(m, {{9, 0}, {91, 0}, {100, 9}, {100, 191}, {91, 200}, {9, 200}, {0, 191}, {0, 9}},
        IM_COL32(30, 29, 36, 255));
    m.quad(0, 0, 20, true);
    const std::vector<UiDrawRun> runs = fills(m, 1000);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_TRUE(runs[0].inside.empty());
    EXPECT_EQ(runs[0].indexCount, 6u);
    EXPECT_EQ(runs[1].indexCount, 18u);
    EXPECT_EQ(runs[1].inside.x0, 0);
    EXPECT_EQ(runs[1].inside.x1, 100);
    EXPECT_EQ(runs[1].inside.y0, 9);
    EXPECT_EQ(runs[1].inside.y1, 191);
    EXPECT_TRUE(runs[2].inside.empty());
}

TEST(UiDrawRuns, TranslucentSmallOrConcaveFillsAreDrawnAsTheyAre) {
    Mesh translucent, small, concave;
    fan(translucent, {{0, 0}, {100, 0}, {100, 100}, {0, 100}}, IM_COL32(30, 29, 36, 247));
    fan(small, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, IM_COL32(30, 29, 36, 255));
    fan(concave, {{0, 0}, {100, 0}, {50, 10}, {100, 100}, {0, 100}}, IM_COL32(30, 29, 36, 255));
    for (const Mesh* m : {&translucent, &small, &concave}) {
        const std::vector<UiDrawRun> runs = fills(*m, 1000);
        ASSERT_EQ(runs.size(), 1u);
        EXPECT_TRUE(runs[0].inside.empty());
    }
}
