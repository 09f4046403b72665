#include "trails.h"

#include <algorithm>

void Trails::record(const World& world) {
    if (world.blocks.size() != blockCount_) {
        blockCount_ = world.blocks.size();
        const std::size_t fit = maxBytes_ / (sizeof(Vec2) * std::max<std::size_t>(1, blockCount_));
        capacity_ =
            static_cast<int>(std::clamp<std::size_t>(fit, 2, static_cast<std::size_t>(wanted_)));
        points_.assign(blockCount_ * static_cast<std::size_t>(capacity_), Vec2{});
        points_.shrink_to_fit();
        length_ = 0;
        head_ = 0;
        skipped_ = 0;
    } else if (length_ > 0 && ++skipped_ < every_) {
        return;
    }
    skipped_ = 0;
    head_ = (head_ + 1) % capacity_;
    for (std::size_t i = 0; i < blockCount_; ++i) {
        points_[i * static_cast<std::size_t>(capacity_) + static_cast<std::size_t>(head_)] =
            world.blocks[i].position;
    }
    if (length_ < capacity_) ++length_;
}

void Trails::clear() {
    length_ = 0;
    skipped_ = 0;
    head_ = 0;
}

Vec2 Trails::point(std::size_t block, int age) const {
    if (block >= blockCount_ || age < 0 || age >= length_) return {};
    const int slot = ((head_ - age) % capacity_ + capacity_) % capacity_;
    return points_[block * static_cast<std::size_t>(capacity_) + static_cast<std::size_t>(slot)];
}

int Trails::ageWithinLength(const World& world, double budget) const {
    if (length_ < 2 || world.blocks.size() != blockCount_) return 0;
    double total = 0.0;
    for (int age = 1; age < length_; ++age) {
        for (std::size_t i = 0; i < blockCount_; ++i) {
            if (world.blocks[i].kind == BodyKind::Static) continue;
            total += ::length(point(i, age) - point(i, age - 1));
        }
        if (total > budget) return age > 1 ? age - 1 : 1;
    }
    return length_ - 1;
}
