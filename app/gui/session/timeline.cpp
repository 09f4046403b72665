#include "timeline.h"

#include <algorithm>

WorldHistory::WorldHistory(std::uint64_t capacityFrames, int keyframeEvery, std::size_t maxBytes)
    : capacity_(std::max<std::uint64_t>(1, capacityFrames)), every_(std::max(1, keyframeEvery)),
      maxBytes_(maxBytes) {}

void WorldHistory::clear() {
    keyframes_.clear();
    haveLast_ = false;
}

void WorldHistory::beforeStep(const World& world) {
    if (!keyframes_.empty() && world.frame < lastFrame()) truncateAfter(world.frame);
    if (!keyframes_.empty() && world.frame < keyframes_.front().frame) clear();
    // An edit between steps is recorded where it is applied (editedAt): here only the keyframe
    // that is due.
    const bool due = keyframes_.empty() ||
                     world.frame >= keyframes_.back().frame + static_cast<std::uint64_t>(every_);
    if (due) {
        while (!keyframes_.empty() && keyframes_.back().frame >= world.frame) {
            keyframes_.pop_back();
        }
        keyframes_.push_back(recycledCopy(world));
    }
}

World WorldHistory::recycledCopy(const World& world) {
    // Past the cap, afterStep drops the oldest keyframe as soon as this one is in: drop it
    // first and copy into its storage, so that a long run past the cap allocates no keyframe
    // (one of 100,000 blocks is 9.6 MB; freeing and allocating one a few times a second
    // fragments the heap). Only for a keyframe of the same capacity, so that bytes() and
    // which keyframes are kept are what they were without the reuse.
    const std::size_t added = sizeof(World) + world.blocks.size() * sizeof(Block);
    if (keyframes_.empty() || bytes() + added <= maxBytes_ ||
        keyframes_.front().blocks.capacity() != world.blocks.size()) {
        return world;
    }
    World spare = std::move(keyframes_.front());
    keyframes_.pop_front();
    spare = world; // the same capacity: no allocation
    return spare;
}

void WorldHistory::afterStep(const World& world) {
    last_ = world;
    haveLast_ = true;
    // Keep `capacity_` frames: drop a keyframe when the next one alone still covers them; and
    // stay within `maxBytes_`, the oldest keyframe going first (the newest is always kept).
    while (keyframes_.size() > 1 && world.frame - keyframes_[1].frame >= capacity_) {
        keyframes_.pop_front();
    }
    while (keyframes_.size() > 1 && bytes() > maxBytes_) keyframes_.pop_front();
}

std::uint64_t WorldHistory::firstFrame() const {
    return keyframes_.empty() ? 0 : keyframes_.front().frame;
}

std::uint64_t WorldHistory::lastFrame() const {
    if (keyframes_.empty()) return 0;
    return haveLast_ ? std::max(last_.frame, keyframes_.back().frame) : keyframes_.back().frame;
}

bool WorldHistory::stateAt(std::uint64_t frame, World& out) const {
    if (keyframes_.empty() || frame < firstFrame() || frame > lastFrame()) return false;
    if (haveLast_ && frame == last_.frame) {
        out = last_;
        return true;
    }
    // The last keyframe at or before `frame`.
    auto it = std::upper_bound(keyframes_.begin(), keyframes_.end(), frame,
                               [](std::uint64_t f, const World& w) { return f < w.frame; });
    if (it == keyframes_.begin()) return false;
    out = *(it - 1);
    while (out.frame < frame) out.step();
    return true;
}

void WorldHistory::truncateAfter(std::uint64_t frame) {
    if (keyframes_.empty() || frame >= lastFrame()) return;
    World at;
    const bool ok = stateAt(frame, at);
    while (!keyframes_.empty() && keyframes_.back().frame > frame) keyframes_.pop_back();
    if (ok) {
        last_ = at;
        haveLast_ = true;
    } else {
        haveLast_ = false;
    }
}

void WorldHistory::editedAt(const World& world) {
    if (keyframes_.empty()) return;
    if (world.frame < keyframes_.front().frame) {
        clear();
        return;
    }
    while (!keyframes_.empty() && keyframes_.back().frame >= world.frame) keyframes_.pop_back();
    keyframes_.push_back(world);
    last_ = world;
    haveLast_ = true;
    // A keyframe every frame while thrust is held: within `maxBytes_` here too.
    while (keyframes_.size() > 1 && bytes() > maxBytes_) keyframes_.pop_front();
}

double WorldHistory::recordedSeconds() const {
    if (keyframes_.empty()) return 0.0;
    const double newest = haveLast_ ? last_.time : keyframes_.back().time;
    return std::max(0.0, newest - keyframes_.front().time);
}

std::vector<CollisionRecord> WorldHistory::collisionsUpTo(std::uint64_t frame, std::size_t count,
                                                          std::size_t budgetBlockSteps) const {
    std::vector<CollisionRecord> found; // newest first while walking back
    if (keyframes_.empty() || count == 0) return found;
    frame = std::min(frame, lastFrame());
    // The last keyframe at or before `frame`; each pass steps one keyframe to the next (or to
    // `frame`), which replays the frames between them with their collisions.
    auto it = std::upper_bound(keyframes_.begin(), keyframes_.end(), frame,
                               [](std::uint64_t f, const World& w) { return f < w.frame; });
    std::uint64_t end = frame;
    std::size_t spent = 0;
    std::vector<CollisionRecord> log, segment;
    while (it != keyframes_.begin() && found.size() < count && spent < budgetBlockSteps) {
        --it;
        World w = *it;
        segment.clear();
        while (w.frame < end) {
            log.clear();
            w.step(&log);
            spent += std::max<std::size_t>(1, w.blocks.size());
            for (const CollisionRecord& r : log) {
                if (!r.rest) segment.push_back(r);
            }
        }
        found.insert(found.end(), segment.rbegin(), segment.rend());
        end = it->frame;
    }
    if (found.size() > count) found.resize(count);
    return std::vector<CollisionRecord>(found.rbegin(), found.rend());
}

std::size_t WorldHistory::bytes() const {
    std::size_t total = sizeof(*this);
    for (const World& w : keyframes_) total += sizeof(World) + w.blocks.capacity() * sizeof(Block);
    return total + last_.blocks.capacity() * sizeof(Block);
}
