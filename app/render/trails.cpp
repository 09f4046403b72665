#include "trails.h"

#include <algorithm>

void Trails::record(const World& world, const std::vector<CollisionRecord>* log) {
    if (world.blocks.size() != blockCount_) {
        blockCount_ = world.blocks.size();
        // A point is its position, its point of impact and whether it has one; each block also
        // holds one pending impact.
        const std::size_t blocks = std::max<std::size_t>(1, blockCount_);
        const std::size_t pending = blocks * (sizeof(Vec2) + 1);
        const std::size_t fit =
            maxBytes_ > pending ? (maxBytes_ - pending) / (kPointBytes * blocks) : 0;
        capacity_ =
            static_cast<int>(std::clamp<std::size_t>(fit, 2, static_cast<std::size_t>(wanted_)));
        points_.assign(blockCount_ * static_cast<std::size_t>(capacity_), Vec2{});
        points_.shrink_to_fit();
        impacts_.assign(points_.size(), Vec2{});
        impacts_.shrink_to_fit();
        hasImpact_.assign(points_.size(), 0);
        hasImpact_.shrink_to_fit();
        pendingImpact_.assign(blockCount_, Vec2{});
        hasPending_.assign(blockCount_, 0);
        length_ = 0;
        head_ = 0;
        skipped_ = 0;
    }
    if (log && world.settings.method != Method::MoveAndCorrect) {
        const auto note = [this](int block, Vec2 at) {
            const auto i = static_cast<std::size_t>(block);
            if (block < 0 || i >= blockCount_ || hasPending_[i]) return;
            pendingImpact_[i] = at;
            hasPending_[i] = 1;
        };
        for (const CollisionRecord& r : *log) {
            if (r.rest) continue; // a resting contact: the block is where it was
            note(r.block, r.position1);
            note(r.other, r.position2);
        }
    }
    if (length_ > 0 && ++skipped_ < every_) return;
    skipped_ = 0;
    head_ = (head_ + 1) % capacity_;
    for (std::size_t i = 0; i < blockCount_; ++i) {
        const std::size_t k = slotIndex(i, head_);
        points_[k] = world.blocks[i].position;
        impacts_[k] = pendingImpact_[i];
        hasImpact_[k] = length_ > 0 ? hasPending_[i] : 0; // a first point has no way to it
        hasPending_[i] = 0;
    }
    if (length_ < capacity_) ++length_;
}

void Trails::clear() {
    hasPending_.assign(blockCount_, 0);
    length_ = 0;
    skipped_ = 0;
    head_ = 0;
}

Vec2 Trails::point(std::size_t block, int age) const {
    if (block >= blockCount_ || age < 0 || age >= length_) return {};
    const int slot = slotOf(age);
    return points_[slotIndex(block, slot)];
}

bool Trails::impact(std::size_t block, int age, Vec2& at) const {
    if (block >= blockCount_ || age < 0 || age + 1 >= length_) return false;
    const int slot = slotOf(age);
    if (!hasImpact_[slotIndex(block, slot)]) return false;
    at = impacts_[slotIndex(block, slot)];
    return true;
}

int Trails::ageWithinLength(const World& world, double budget) const {
    if (length_ < 2 || world.blocks.size() != blockCount_) return 0;
    // Every frame, up to length() x blocks steps: each age's slot found once, the blocks' points
    // read straight from it (the same sums in the same order as through point()).
    double total = 0.0;
    for (int age = 1; age < length_; ++age) {
        const int newer = slotOf(age - 1), older = slotOf(age);
        for (std::size_t i = 0; i < blockCount_; ++i) {
            if (world.blocks[i].kind == BodyKind::Static) continue;
            total += ::length(points_[slotIndex(i, older)] - points_[slotIndex(i, newer)]);
        }
        if (total > budget) return age > 1 ? age - 1 : 1;
    }
    return length_ - 1;
}
