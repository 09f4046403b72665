// The timeline: a history of the world the user scrubs back through and steps forward from.
// Keyframes (whole World copies) every `keyframeEvery` frames, plus a keyframe wherever an edit
// was applied between steps (editedAt: the session's one door calls it for every edit, so no
// field can be missed); any frame in between is rebuilt by stepping its
// keyframe forward, which the engine's determinism makes bit-exact. Memory: 1,000 blocks, 60 s
// at 60 Hz, a keyframe every 12 frames: 300 x 64 kB = 19 MB; whatever the scene (200,000
// blocks, or a keyframe every frame while thrust is held), at most kTimelineMaxBytes: the oldest
// keyframes go first, so the timeline reaches back less far. Pure logic, no ImGui.
#pragma once

#include "world.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

// The timeline's cap: 128 MiB of keyframes (README, "Memory in long runs").
inline constexpr std::size_t kTimelineMaxBytes = std::size_t{128} << 20;

class WorldHistory {
  public:
    explicit WorldHistory(std::uint64_t capacityFrames = 3600, int keyframeEvery = 12,
                          std::size_t maxBytes = kTimelineMaxBytes);

    void clear();
    // Call with the live world just before it steps: truncates the future when the world was
    // scrubbed back, and stores a keyframe when one is due.
    void beforeStep(const World& world);
    // Call with the live world just after it stepped.
    void afterStep(const World& world);

    bool empty() const { return keyframes_.empty(); }
    std::uint64_t firstFrame() const; // oldest frame that can be rebuilt
    std::uint64_t lastFrame() const;  // newest recorded frame
    // Rebuilds the world at `frame` (firstFrame()..lastFrame()) into `out`; false if outside.
    bool stateAt(std::uint64_t frame, World& out) const;
    // Drops everything after `frame`.
    void truncateAfter(std::uint64_t frame);
    // The world was edited (a drag, a slider) at its frame: the edited state becomes the newest
    // recorded one, and the recorded future after it is dropped (a new future starts there).
    void editedAt(const World& world);
    // Seconds of simulated time from the oldest to the newest recorded frame (the frames' own
    // times, so a change of frame rate on the way is counted right).
    double recordedSeconds() const;
    // The last `count` collisions (the rest rule's contacts left out) resolved in the frames up
    // to and including `frame`, oldest first: what the inspector lists when the timeline shows
    // `frame`. Rebuilt by stepping the keyframes again (bit-exact, as stateAt), walking back
    // from `frame` until `count` are found, the history ends, or about `budgetBlockSteps`
    // block-steps were spent (a big scene far from its last collision).
    std::vector<CollisionRecord> collisionsUpTo(std::uint64_t frame, std::size_t count,
                                                std::size_t budgetBlockSteps = 200000) const;
    std::size_t keyframeCount() const { return keyframes_.size(); }
    std::size_t bytes() const;
    std::size_t maxBytes() const { return maxBytes_; }

  private:
    World recycledCopy(const World& world); // a copy of world, in the oldest's storage if due
    std::uint64_t capacity_;
    int every_;
    std::size_t maxBytes_;
    std::deque<World> keyframes_; // ascending frame numbers
    World last_;                  // the live world after the last recorded step
    bool haveLast_ = false;
};
