// The perfect method's index of paths: each block's swept box for the rest of the substep, which
// both the predictions (impact_search.h) and the rest rule (Resolver, as its BlockFinder) read.
#pragma once

#include "broad_phase.h"
#include "corner_grid.h"
#include "resolve.h"

#include <vector>

// A CornerGrid (one entry per block, cheap to build for blocks of similar size), or the BroadPhase
// when the sizes are too mixed for it. Both answer every query with the same blocks, in different
// orders, on which nothing depends (each pair is predicted once per pair of stamps; the rest rule
// sorts its cluster).
class PathIndex final : public BlockFinder {
  public:
    PathIndex(CornerGrid& cornerGrid, BroadPhase& broadPhase)
        : cornerGrid_(cornerGrid), broadPhase_(broadPhase) {}

    // Registers every block i with the path pathOf(i), called once per block in index order.
    template <class PathOf>
    void build(const Bounds& bounds, const std::vector<Block>& blocks, PathOf&& pathOf) {
        useCornerGrid_ = cornerGrid_.build(bounds, blocks, pathOf);
        if (!useCornerGrid_)
            broadPhase_.build(bounds, blocks, [&](int i) { return cornerGrid_.box(i); });
    }
    const Aabb& path(int i) const {
        return useCornerGrid_ ? cornerGrid_.box(i) : broadPhase_.box(i);
    }
    void set(int i, const Aabb& path) {
        if (useCornerGrid_)
            cornerGrid_.set(i, path);
        else
            broadPhase_.set(i, path);
    }
    // visit(j) for every block j other than `self` whose path meets `box`.
    template <class Visit> void queryOthers(const Aabb& box, int self, Visit&& visit) const {
        if (useCornerGrid_)
            cornerGrid_.queryOthers(box, self, visit);
        else
            broadPhase_.queryOthers(box, self, visit);
    }
    // visit(i, j) for every pair of paths that meet (right after build()).
    template <class Visit> void forEachMeetingPair(Visit&& visit) const {
        if (useCornerGrid_)
            cornerGrid_.forEachMeetingPair(visit);
        else
            broadPhase_.forEachMeetingPair(visit);
    }
    void find(const Aabb& box, std::vector<int>& found) const override {
        queryOthers(box, -1, [&](int j) { found.push_back(j); });
    }

  private:
    CornerGrid& cornerGrid_;
    BroadPhase& broadPhase_;
    bool useCornerGrid_ = true;
};
