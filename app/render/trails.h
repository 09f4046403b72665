// Trails: the recent positions of every block (the lecture's D key draws them, C clears them).
// A ring buffer per block in one flat array; pure logic, drawn by the renderer with fading alpha.
// A trail draws the path that happened: with the perfect and turn-based methods a block that
// collided on the way to a stored point passes through its point of impact (lecture, "Point of
// Impact"), kept beside that point, rather than cutting the corner from one frame's end to the
// next.
#pragma once

#include "stats.h"
#include "vec2.h"
#include "world.h"

#include <cstddef>
#include <vector>

// The trails' cap: 32 MiB of points (README, "Memory in long runs"). A scene of more blocks than
// fit 90 points each keeps fewer points per block (at least 2): 11,233 blocks still get 90.
inline constexpr std::size_t kTrailsMaxBytes = std::size_t{32} << 20;
// A stored point: its position, its point of impact (16 bytes each) and whether it has one.
inline constexpr std::size_t kPointBytes = 2 * sizeof(Vec2) + 1;

class Trails {
  public:
    // `capacity` points per block, one every `every` recorded frames (default: 3 s at 60 Hz),
    // fewer when the blocks' points would pass `maxBytes`.
    explicit Trails(int capacity = 90, int every = 2, std::size_t maxBytes = kTrailsMaxBytes)
        : wanted_(capacity < 2 ? 2 : capacity), capacity_(wanted_), every_(every < 1 ? 1 : every),
          maxBytes_(maxBytes) {}

    // Appends the current position of every block. A change in the number of blocks (a block
    // added or removed) restarts every trail, since indices no longer name the same blocks.
    // `log`, the collisions of the frame just stepped: each block's first point of impact since
    // its last stored point is kept with the next one (not with move-and-correct, whose resolve
    // happens after the overlap, at no point of the path).
    void record(const World& world, const std::vector<CollisionRecord>* log = nullptr);
    void clear();

    int capacity() const { return capacity_; } // points per block now (see maxBytes)
    std::size_t bytes() const {
        return (points_.capacity() + impacts_.capacity() + pendingImpact_.capacity()) *
                   sizeof(Vec2) +
               hasImpact_.capacity() + hasPending_.capacity();
    }
    std::size_t maxBytes() const { return maxBytes_; }
    std::size_t blockCount() const { return blockCount_; }
    // Number of points stored for each block (the same for all blocks).
    int length() const { return length_; }
    // Point `age` of block `block`: age 0 is the newest, length() - 1 the oldest.
    Vec2 point(std::size_t block, int age) const;
    // The point of impact on the way from point age + 1 to point age, if the block collided
    // there (then `at` is where it touched).
    bool impact(std::size_t block, int age, Vec2& at) const;
    // The same for a loop over every block at the same ages (the scene's drawing): the slot of
    // point `age` (0 <= age < length()) found once, then each block's point in that slot, and its
    // point of impact there (for an age + 1 < length()), with no check of the block or the age.
    int slotOfAge(int age) const { return slotOf(age); }
    Vec2 pointIn(std::size_t block, int slot) const { return points_[slotIndex(block, slot)]; }
    bool impactIn(std::size_t block, int slot, Vec2& at) const {
        if (!hasImpact_[slotIndex(block, slot)]) return false;
        at = impacts_[slotIndex(block, slot)];
        return true;
    }
    // The oldest age (at least 1, at most length() - 1) up to which the trails of the moving blocks
    // of `world` are together no longer than `budget` metres, all cut at the same age; 0 when
    // there is no trail to draw. Drawing costs in proportion to length on a software rasteriser,
    // so a crowded scene shows the newest part of every trail instead of all of a few.
    int ageWithinLength(const World& world, double budget) const;

  private:
    int wanted_;   // points per block asked for
    int capacity_; // points per block kept: wanted_, or fewer within maxBytes_
    int every_;
    std::size_t maxBytes_;
    int skipped_ = 0; // frames since the last stored point
    std::size_t blockCount_ = 0;
    int length_ = 0;
    int head_ = 0;             // slot of the newest point
    std::vector<Vec2> points_; // blockCount_ * capacity_
    // Beside each point: the first point of impact on the way to it (impacts_), and whether there
    // was one (hasImpact_); pending*_: what the frames since the last stored point met.
    std::vector<Vec2> impacts_;
    std::vector<char> hasImpact_;
    std::vector<Vec2> pendingImpact_;
    std::vector<char> hasPending_;

    // The slot of point `age` (0: the newest).
    int slotOf(int age) const { return ((head_ - age) % capacity_ + capacity_) % capacity_; }
    std::size_t slotIndex(std::size_t block, int slot) const {
        return block * static_cast<std::size_t>(capacity_) + static_cast<std::size_t>(slot);
    }
};
