#include "crush.h"

#include <utility>

void CrushRule::reset(size_t blockCount) {
    if (bounces_.size() != 2 * blockCount) {
        bounces_.assign(2 * blockCount, Bounce{});
    } else {
        for (size_t k : used_) bounces_[k] = Bounce{};
    }
    used_.clear();
}

bool CrushRule::squeezed(const std::vector<Block>& blocks, int a, int other, int axis,
                         double positionA, double positionOther) {
    int block = a, anchor = other;
    double blockPosition = positionA, anchorPosition = positionOther;
    if (other >= 0) {
        if (blocks[a].isDynamic() == blocks[other].isDynamic()) return false;
        if (!blocks[a].isDynamic()) {
            std::swap(block, anchor);
            std::swap(blockPosition, anchorPosition);
        }
    } else if (!blocks[block].isDynamic()) {
        return false;
    }
    const int side = anchor < 0 ? (blocks[block].velocity[axis] > 0.0 ? 1 : -1)
                                : (anchorPosition > blockPosition ? 1 : -1);
    const size_t entry = 2 * static_cast<size_t>(block) + axis;
    Bounce& last = bounces_[entry];
    if (last.side == 0) used_.push_back(entry); // the first change since the reset
    auto velocityOf = [&](int body) { return body < 0 ? 0.0 : blocks[body].velocity[axis]; };
    // The lower and upper anchor close in when the lower one moves up faster than the upper.
    const double lower = velocityOf(side > 0 ? last.anchor : anchor);
    const double upper = velocityOf(side > 0 ? anchor : last.anchor);
    if (last.side == -side && lower - upper > 0.0)
        ++last.alternations;
    else
        last.alternations = 0;
    last.anchor = anchor;
    last.side = side;
    return last.alternations > kSqueezeBounces;
}
