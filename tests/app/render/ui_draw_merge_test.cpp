// The browser's UI draws (ui_draw_merge.h): which of ImGui's commands become one draw, and
// under which scissor box (no GL).
#include "ui_draw_merge.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace {

ImTextureID texture(std::intptr_t id) {
    return reinterpret_cast<ImTextureID>(id);
}

const UiScissor kLeft{0, 0, 100, 100}, kRight{200, 0, 100, 100};

} // namespace

// Windows whose contents their boxes do not clip: one draw under a box holding both.
TEST(UiDrawMerge, UnclippedNeighboursAreOneDrawUnderABoxHoldingBoth) {
    UiDrawMerger m;
    m.add(0, 30, texture(1), kLeft, {10, 10, 90, 90});
    m.add(30, 60, texture(1), kRight, {200, 0, 300, 100}); // touching its box's edges: inside
    ASSERT_EQ(m.draws().size(), 1u);
    EXPECT_EQ(m.draws()[0].first, 0u);
    EXPECT_EQ(m.draws()[0].count, 90u);
    EXPECT_EQ(m.draws()[0].box, (UiScissor{0, 0, 300, 100}));
}

// A command its box clips keeps that box: its neighbours join only when that box keeps all of
// theirs, and a second clipped one only with the same box.
TEST(UiDrawMerge, AClippedCommandKeepsItsBox) {
    UiDrawMerger m;
    m.add(0, 6, texture(1), kLeft, {10, 10, 90, 90});
    m.add(6, 6, texture(1), kLeft, {50, 50, 150, 90}); // text cut at the window's edge
    m.add(12, 6, texture(1), kLeft, {20, 20, 30, 30});
    m.add(18, 6, texture(1), kLeft, {80, 10, 120, 20});   // clipped, the same box: joins
    m.add(24, 6, texture(1), kRight, {210, 10, 220, 20}); // outside kLeft: a new draw
    ASSERT_EQ(m.draws().size(), 2u);
    EXPECT_EQ(m.draws()[0].count, 24u);
    EXPECT_EQ(m.draws()[0].box, kLeft);
    EXPECT_EQ(m.draws()[1].box, kRight);
    // Clipped after unclipped neighbours that its box holds: joins, under its box.
    UiDrawMerger n;
    n.add(0, 6, texture(1), kLeft, {10, 10, 90, 90});
    n.add(6, 6, texture(1), kLeft, {50, 50, 150, 90});
    ASSERT_EQ(n.draws().size(), 1u);
    EXPECT_EQ(n.draws()[0].box, kLeft);
    // ... but not when the earlier ones reach outside it (it would cut them).
    UiDrawMerger o;
    o.add(0, 6, texture(1), kRight, {210, 10, 290, 90});
    o.add(6, 6, texture(1), kLeft, {50, 50, 150, 90});
    EXPECT_EQ(o.draws().size(), 2u);
    // A clipped one with another box than the draw's: a new draw.
    UiDrawMerger q;
    q.add(0, 6, texture(1), kLeft, {50, 50, 150, 90});
    q.add(6, 6, texture(1), UiScissor{0, 0, 120, 100}, {60, 50, 130, 90});
    EXPECT_EQ(q.draws().size(), 2u);
}

// Another texture, indices not next to the draw's, or a callback between: separate draws.
TEST(UiDrawMerge, OtherTexturesGapsAndCallbacksPart) {
    UiDrawMerger m;
    m.add(0, 6, texture(1), kLeft, {10, 10, 20, 20});
    m.add(6, 6, texture(2), kLeft, {10, 10, 20, 20});
    m.add(15, 6, texture(2), kLeft, {10, 10, 20, 20});
    ImDrawCmd cmd;
    m.addCallback(nullptr, &cmd);
    m.add(21, 6, texture(2), kLeft, {10, 10, 20, 20});
    ASSERT_EQ(m.draws().size(), 5u);
    EXPECT_EQ(m.draws()[3].callback, &cmd);
    EXPECT_EQ(m.draws()[3].count, 0u);
}
