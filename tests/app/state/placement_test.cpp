#include "placement.h"

#include <gtest/gtest.h>

namespace {

Block box(Vec2 p, Vec2 size, BodyKind kind = BodyKind::Dynamic) {
    Block b;
    b.position = p;
    b.size = size;
    b.kind = kind;
    b.mass = kind == BodyKind::Dynamic ? 1.0 : kInfiniteMass;
    return b;
}

World worldWith(std::initializer_list<Block> blocks) {
    World w;
    w.bounds.min = {0.0, 0.0};
    w.bounds.max = {20.0, 12.0};
    w.blocks = blocks;
    return w;
}

// Positive-area overlap between block i and every other block (touching is fine).
bool anyOverlap(const World& w, int i) {
    return overlapsAnyBlock(w, i, w.blocks[static_cast<std::size_t>(i)].position,
                            w.blocks[static_cast<std::size_t>(i)].size);
}

TEST(Picking, FindsTheTopmostBlockUnderThePoint) {
    const World w = worldWith({box({5, 5}, {4, 4}), box({5, 5}, {1, 1})});
    EXPECT_EQ(pickBlock(w, {5.2, 5.2}, 0.0), 1); // drawn last, so on top
    EXPECT_EQ(pickBlock(w, {6.5, 6.5}, 0.0), 0);
    EXPECT_EQ(pickBlock(w, {15, 5}, 0.0), -1);
}

TEST(Picking, ToleranceGrabsThinBlocks) {
    const World w = worldWith({box({5, 5}, {3, 0.05})});
    EXPECT_EQ(pickBlock(w, {5, 5.1}, 0.0), -1);
    EXPECT_EQ(pickBlock(w, {5, 5.1}, 0.1), 0);
}

TEST(Placement, AFreeSpotIsKept) {
    const World w = worldWith({box({5, 5}, {1, 1})});
    const auto p = placeWithoutOverlap(w, -1, {10, 6}, {1, 1});
    ASSERT_TRUE(p);
    EXPECT_EQ(*p, (Vec2{10, 6}));
}

TEST(Placement, IsClampedIntoTheBounds) {
    const World w = worldWith({});
    const auto p = placeWithoutOverlap(w, -1, {25, -3}, {2, 2});
    ASSERT_TRUE(p);
    EXPECT_EQ(*p, (Vec2{19, 1}));
}

TEST(Placement, ADropOntoABlockLandsBesideIt) {
    World w = worldWith({box({5, 5}, {2, 2}), box({12, 8}, {1, 1})});
    // Drag block 1 onto block 0, a little right of its centre: the nearest free spot is to the
    // right, touching.
    w.blocks[1].position = {5.4, 5.1};
    const auto p = placeWithoutOverlap(w, 1, w.blocks[1].position, w.blocks[1].size);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, 6.5, 1e-5);
    EXPECT_NEAR(p->y, 5.1, 1e-12);
    w.blocks[1].position = *p;
    EXPECT_FALSE(anyOverlap(w, 1));
}

TEST(Placement, FindsASpotInACrowdWithoutOverlap) {
    // A row of blocks; dropping onto the middle one must not land on a neighbour.
    World w = worldWith(
        {box({4, 1}, {2, 2}), box({6, 1}, {2, 2}), box({8, 1}, {2, 2}), box({15, 6}, {2, 2})});
    w.blocks[3].position = {6.2, 1.2};
    const auto p = placeWithoutOverlap(w, 3, w.blocks[3].position, w.blocks[3].size);
    ASSERT_TRUE(p);
    w.blocks[3].position = *p;
    EXPECT_FALSE(anyOverlap(w, 3));
    EXPECT_NEAR(p->y, 3.0, 1e-5); // on top of the row is nearest
}

TEST(Placement, StaticBlocksAreObstaclesToo) {
    World w = worldWith({box({10, 1}, {20, 2}, BodyKind::Static)});
    const auto p = placeWithoutOverlap(w, -1, {10, 1.5}, {1, 1});
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->y, 2.5, 1e-5);
}

TEST(Placement, NoRoomGivesNothing) {
    World w = worldWith({box({10, 6}, {20, 12}, BodyKind::Static)});
    EXPECT_FALSE(placeWithoutOverlap(w, -1, {10, 6}, {1, 1}));
}

TEST(Placement, NonFiniteInputIsRejected) {
    const World w = worldWith({});
    EXPECT_FALSE(placeWithoutOverlap(w, -1, {std::nan(""), 1}, {1, 1}));
}

} // namespace
