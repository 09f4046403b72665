#include "ui_draw_merge.h"

#include <algorithm>
#include <cmath>

namespace {

// The reach of no triangle: within every box.
constexpr UiReach kNowhere{INFINITY, INFINITY, -INFINITY, -INFINITY};

UiScissor unite(const UiScissor& a, const UiScissor& b) {
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width);
    const int y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}

UiReach unite(const UiReach& a, const UiReach& b) {
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

} // namespace

void UiDrawMerger::clear() {
    draws_.clear();
    fixed_ = false;
}

void UiDrawMerger::add(std::size_t first, std::size_t count, ImTextureID texture,
                       const UiScissor& box, const UiReach& reach) {
    const bool clipped = !reach.within(box); // its own box cuts some of its pixels
    if (!draws_.empty()) {
        UiMergedDraw& last = draws_.back();
        if (!last.callback && last.texture == texture && last.first + last.count == first) {
            bool joins = false;
            UiScissor joined = last.box;
            if (clipped) { // its own box it must have, and it must keep all of the draw's
                joins = (!fixed_ || last.box == box) && reach_.within(box);
                joined = box;
            } else if (fixed_) {
                joins = reach.within(last.box);
            } else { // boxes that clip nothing: one holding both
                joins = true;
                joined = unite(last.box, box);
            }
            if (joins) {
                last.count += count;
                last.box = joined;
                fixed_ = fixed_ || clipped;
                if (!clipped) reach_ = unite(reach_, reach);
                return;
            }
        }
    }
    UiMergedDraw d;
    d.first = first;
    d.count = count;
    d.texture = texture;
    d.box = box;
    draws_.push_back(d);
    fixed_ = clipped;
    reach_ = clipped ? kNowhere : reach;
}

void UiDrawMerger::addCallback(const ImDrawList* list, const ImDrawCmd* cmd) {
    UiMergedDraw d;
    d.list = list;
    d.callback = cmd;
    draws_.push_back(d);
}
