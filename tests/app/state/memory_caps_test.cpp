// Memory stays bounded in long runs (issue 28): the timeline, the trails and what the plots
// record each have a cap in bytes (README, "Memory in long runs"), so a long run stays flat once
// it is reached, whatever the number of blocks, and held thrust (a keyframe every frame) too.
#include "telemetry.h"
#include "timeline.h"
#include "trails.h"
#include "world.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace {

// `n` blocks of 0.5 m on a grid, moving, no gravity: a gas that keeps colliding.
World gas(int n) {
    World w;
    w.bounds = {{0, 0}, {40, 40}};
    w.settings.gravity = {0, 0};
    for (int i = 0; i < n; ++i) {
        Block b;
        b.position = {1.0 + (i % 30) * 1.2, 1.0 + (i / 30) * 1.2};
        b.size = {0.5, 0.5};
        b.velocity = {(i % 7) - 3.0, (i % 5) - 2.0};
        b.mass = 1.0;
        w.blocks.push_back(b);
    }
    return w;
}

} // namespace

TEST(MemoryCaps, TimelineStaysFlatAtItsCapWithThrustHeld) {
    // A cap of 2 MB on 300 blocks, a keyframe every frame (as while thrust is held: editedAt):
    // once the cap is reached the bytes stay within it frame after frame.
    const std::size_t cap = std::size_t{2} << 20;
    WorldHistory history(3600, 12, cap);
    World w = gas(300);
    std::size_t atCap = 0;
    for (int frame = 0; frame < 1500; ++frame) {
        history.beforeStep(w);
        w.step();
        history.afterStep(w);
        history.editedAt(w);
        ASSERT_LE(history.bytes(), cap) << "frame " << frame;
        if (frame == 750) atCap = history.bytes();
    }
    // Flat: the same keyframes' worth at frame 750 and at the end (each keyframe is one world of
    // 300 blocks, so the count kept is the same).
    EXPECT_GT(atCap, cap - cap / 10);
    EXPECT_EQ(history.bytes(), atCap);
    EXPECT_LT(history.firstFrame(), history.lastFrame()); // still a timeline to scrub
}

TEST(MemoryCaps, TimelineDefaultCapIs128MiB) {
    EXPECT_EQ(WorldHistory().maxBytes(), std::size_t{128} * 1024 * 1024);
}

TEST(MemoryCaps, TrailsKeepFewerPointsForManyBlocks) {
    // 90 points a block fit 11,233 blocks in 32 MiB (33 bytes a point: its position, its point
    // of impact, whether it has one; 17 bytes a block pending); 200,000 blocks keep 4.
    Trails small;
    small.record(gas(1000));
    EXPECT_EQ(small.capacity(), 90);
    World many;
    many.blocks.resize(200000);
    Trails big;
    big.record(many);
    EXPECT_EQ(big.capacity(), 4); // floor((32 MiB - 17 B x 200,000) / (33 B x 200,000))
    EXPECT_LE(big.bytes(), kTrailsMaxBytes);
    for (int i = 0; i < 50; ++i) big.record(many);
    EXPECT_LE(big.bytes(), kTrailsMaxBytes); // flat: a ring buffer
    EXPECT_EQ(big.length(), 4);
}

TEST(MemoryCaps, PlotsRecordABoundedAmount) {
    // Whatever the run: three series of 3,600 samples (times and 2, 2 and 3 channels), 512
    // collision markers twice, 24 recent collisions, 20,000 velocity-space samples.
    const std::size_t bound = 3600 * (3 + 2 + 2 + 3) * sizeof(double) + 2 * 512 * sizeof(double) +
                              24 * sizeof(CollisionRecord) +
                              VelocitySpacePath::kMaxSamples * sizeof(VelocitySpaceSample);
    Telemetry t;
    World w = gas(300);
    std::vector<CollisionRecord> log;
    for (int frame = 0; frame < 5000; ++frame) {
        log.clear();
        w.step(&log);
        t.record(w, 0, log);
        ASSERT_LE(t.bytes(), bound) << "frame " << frame;
    }
    EXPECT_GT(t.collisionTimes.size(), 0u); // it did collide
}
