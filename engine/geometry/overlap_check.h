// Finds a pair of overlapping boxes among many in O(n log n), for any layout (no quadratic worst
// case for tall columns or long rows). Used to validate scenes (a dynamic or kinematic block may
// not start overlapping another block; static blocks may overlap each other).
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace overlap_check {

// An axis-aligned box; boxes overlap when they share positive area (touching is not overlap).
// Fixed boxes (static blocks) may overlap each other.
struct Box {
    double minX, minY, maxX, maxY;
    bool fixed = false;
};

// Coverage counts over the elementary y intervals between the given coordinates (range add,
// range max), so "does any active fixed box meet this y span?" costs O(log n) even when the
// fixed boxes overlap each other.
class Coverage {
  public:
    explicit Coverage(std::vector<double> ys) : ys_(std::move(ys)) {
        std::sort(ys_.begin(), ys_.end());
        ys_.erase(std::unique(ys_.begin(), ys_.end()), ys_.end());
        n_ = std::max<std::size_t>(1, ys_.size());
        max_.assign(4 * n_, 0);
        add_.assign(4 * n_, 0);
    }
    // Adds `delta` over [lo, hi]; both must be among the constructor's coordinates.
    void add(double lo, double hi, int delta) { update(1, 0, n_, index(lo), index(hi), delta); }
    // True when an interval with a positive count meets the open span (lo, hi).
    bool covers(double lo, double hi) const {
        // Elementary interval k is [ys_[k], ys_[k+1]]; it meets (lo, hi) iff ys_[k] < hi and
        // ys_[k+1] > lo.
        const std::size_t first = std::upper_bound(ys_.begin(), ys_.end(), lo) - ys_.begin();
        const std::size_t end = std::lower_bound(ys_.begin(), ys_.end(), hi) - ys_.begin();
        const std::size_t from = first == 0 ? 0 : first - 1;
        return from < end && query(1, 0, n_, from, end) > 0;
    }

  private:
    std::size_t index(double y) const {
        return std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin();
    }
    void update(std::size_t node, std::size_t l, std::size_t r, std::size_t a, std::size_t b,
                int delta) {
        if (b <= l || r <= a) return;
        if (a <= l && r <= b) {
            max_[node] += delta;
            add_[node] += delta;
            return;
        }
        const std::size_t m = (l + r) / 2;
        update(2 * node, l, m, a, b, delta);
        update(2 * node + 1, m, r, a, b, delta);
        max_[node] = add_[node] + std::max(max_[2 * node], max_[2 * node + 1]);
    }
    int query(std::size_t node, std::size_t l, std::size_t r, std::size_t a, std::size_t b) const {
        if (b <= l || r <= a) return 0;
        if (a <= l && r <= b) return max_[node];
        const std::size_t m = (l + r) / 2;
        return add_[node] + std::max(query(2 * node, l, m, a, b), query(2 * node + 1, m, r, a, b));
    }
    std::vector<double> ys_;
    std::size_t n_ = 1;
    std::vector<int> max_, add_;
};

inline bool overlaps(const Box& a, const Box& b) {
    return a.minX < b.maxX && b.minX < a.maxX && a.minY < b.maxY && b.minY < a.maxY;
}

// Returns two overlapping boxes (not both fixed), or nothing. A vertical line sweeps over x.
// Active free boxes cannot overlap each other (else we would have stopped), so their y spans are
// disjoint and sit in a map keyed by their lower edge; active fixed boxes go into the coverage
// tree. Each box is checked when the line reaches its left edge.
inline std::optional<std::pair<std::size_t, std::size_t>>
findOverlap(const std::vector<Box>& boxes) {
    struct Event {
        double x;
        bool enter;
        std::size_t box;
    };
    std::vector<Event> events;
    std::vector<double> fixedYs;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        // A box without area overlaps nothing; in the sweep it would leave before it enters
        // (and then never leave). Scene files cannot make one (input_limits.h), code might.
        if (!(boxes[i].minX < boxes[i].maxX && boxes[i].minY < boxes[i].maxY)) continue;
        events.push_back({boxes[i].minX, true, i});
        events.push_back({boxes[i].maxX, false, i});
        if (boxes[i].fixed) {
            fixedYs.push_back(boxes[i].minY);
            fixedYs.push_back(boxes[i].maxY);
        }
    }
    // Leaving before entering at the same x: touching is not overlap.
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
        return a.x != b.x ? a.x < b.x : (a.enter != b.enter ? !a.enter : a.box < b.box);
    });
    std::map<double, std::size_t> free; // lower edge -> box index
    Coverage fixed(fixedYs);
    for (const Event& e : events) {
        const Box& b = boxes[e.box];
        if (!e.enter) {
            if (b.fixed)
                fixed.add(b.minY, b.maxY, -1);
            else
                free.erase(b.minY);
            continue;
        }
        // The free box with the highest lower edge below b.maxY is the only candidate.
        const auto it = free.lower_bound(b.maxY);
        if (it != free.begin() && boxes[std::prev(it)->second].maxY > b.minY)
            return std::make_pair(std::prev(it)->second, e.box);
        if (b.fixed) {
            fixed.add(b.minY, b.maxY, +1);
            continue;
        }
        if (fixed.covers(b.minY, b.maxY)) {
            for (std::size_t j = 0; j < boxes.size(); ++j) // which one: once, O(n)
                if (boxes[j].fixed && overlaps(boxes[j], b)) return std::make_pair(j, e.box);
        }
        free.emplace(b.minY, e.box);
    }
    return std::nullopt;
}

} // namespace overlap_check
