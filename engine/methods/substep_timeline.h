// The perfect method's substep as a timeline (perfect.cpp): each block moved lazily, its position
// and velocity valid at its own clock, and the impacts predicted ahead, earliest first. Every
// change of a block's velocity increments its stamp; a prediction made with an older stamp is
// stale and skipped. Shared by the loop (perfect.cpp) and the search that predicts
// (impact_search.h).
#pragma once

#include "crush.h"
#include "methods.h"
#include "scratch.h"

#include <algorithm>
#include <cstdint>
#include <vector>

using Event = PerfectScratch::Event;
using Motion = PerfectScratch::Motion;
constexpr int kWallEvent = CrushRule::kWall; // Event::b for an impact with the bounds
// Event::b for a block that stops sliding along x (kStopEvent) or y (kStopEvent - 1): friction
// with the exact integrator (resolve.h, Resolver::stopSliding).
constexpr int kStopEvent = -10;
inline bool isStop(const Event& e) {
    return e.b <= kStopEvent;
}
inline int stopAxis(const Event& e) {
    return kStopEvent - e.b;
}

class SubstepTimeline {
  public:
    SubstepTimeline(SubstepContext& ctx, PerfectScratch& scratch)
        : ctx_(ctx), blocks_(ctx.world.blocks), clock_(scratch.clock), stamp_(scratch.stamp),
          events_(scratch.events) {}

    // Every clock and stamp at 0, no predictions.
    void reset() {
        clock_.assign(blocks_.size(), 0.0);
        stamp_.assign(blocks_.size(), 0);
        events_.clear();
        heap_ = false;
    }

    // The Euler integrators: every block moves on a straight line within the substep.
    bool linear() const { return linear_; }
    double clock(int i) const { return clock_[i]; }
    // A block's position and velocity at time t (its own are valid at its clock); its motion
    // (linear, or a parabola with the exact integrator) is the context's.
    Vec2 positionAt(int i, double t) const {
        if (linear_) return blocks_[i].position + blocks_[i].velocity * (t - clock_[i]);
        return ctx_.positionAfter(i, blocks_[i].position, blocks_[i].velocity, t - clock_[i]);
    }
    Vec2 velocityAt(int i, double t) const {
        return linear_ ? blocks_[i].velocity
                       : ctx_.velocityAfter(i, blocks_[i].velocity, t - clock_[i]);
    }
    // The same from a motion it had (impact_search.cpp, "Windows"): the same arithmetic.
    Vec2 positionAt(int i, const Motion& m, double t) const {
        if (linear_) return m.position + m.velocity * (t - m.clock);
        return ctx_.positionAfter(i, m.position, m.velocity, t - m.clock);
    }
    Vec2 velocityAt(int i, const Motion& m, double t) const {
        return linear_ ? m.velocity : ctx_.velocityAfter(i, m.velocity, t - m.clock);
    }
    Motion motion(int i) const { return {blocks_[i].position, blocks_[i].velocity, clock_[i]}; }
    // The box block i sweeps from `now` to the end of the substep.
    Aabb trajectory(int i, double now) const {
        if (linear_)
            return sweptAabb(positionAt(i, now), blocks_[i].size, blocks_[i].velocity,
                             ctx_.h - now);
        return ctx_.path(i, positionAt(i, now), blocks_[i].size, velocityAt(i, now), ctx_.h - now);
    }
    // Moves block i to time `now` (its clock). Returns false if it was there already (it is
    // moved by nothing all the same, as it always was: a zero's sign may change).
    bool bringTo(int i, double now) {
        double& clock = clock_[i];
        const bool moves = clock != now;
        Block& b = blocks_[i];
        if (!linear_) { // along its parabola: the velocity changes too
            const double t = now - clock;
            b.position = ctx_.positionAfter(i, b.position, b.velocity, t);
            b.velocity = ctx_.velocityAfter(i, b.velocity, t);
        } else {
            b.position += b.velocity * (now - clock);
        }
        clock = now;
        return moves;
    }

    std::uint32_t stamp(int i) const { return stamp_[i]; }
    // Block i's velocity (or acceleration) has changed: its predictions are stale.
    void restamp(int i) { ++stamp_[i]; }

    // Adds a prediction. The first ones (all stamps 0) are only collected, and made a heap by
    // startQueue(): each (a, b) pair is predicted once per pair of stamps, so no two current
    // events compare equal and the order of processing does not depend on the heap's layout.
    void schedule(const Event& e) {
        events_.push_back(e);
        if (heap_) std::push_heap(events_.begin(), events_.end(), Later{});
    }
    void startQueue() {
        std::make_heap(events_.begin(), events_.end(), Later{});
        heap_ = true;
    }
    bool empty() const { return events_.empty(); }
    double earliestTime() const { return events_.front().time; }
    Event popEarliest() {
        std::pop_heap(events_.begin(), events_.end(), Later{});
        const Event e = events_.back();
        events_.pop_back();
        return e;
    }
    bool isStale(const Event& e) const {
        return e.stampA != stamp_[e.a] || (e.b >= 0 && e.stampB != stamp_[e.b]);
    }

  private:
    // Earliest first; ties in a fixed order so runs are deterministic.
    struct Later {
        bool operator()(const Event& x, const Event& y) const {
            if (x.time != y.time) return x.time > y.time;
            if (x.a != y.a) return x.a > y.a;
            return x.b > y.b;
        }
    };

    const SubstepContext& ctx_;
    std::vector<Block>& blocks_;
    const bool linear_ = ctx_.acceleration == nullptr;
    std::vector<double>& clock_;        // s: the time at which each block's position is valid
    std::vector<std::uint32_t>& stamp_; // incremented on every change of velocity
    std::vector<Event>& events_;        // predicted impacts (see schedule())
    bool heap_ = false;                 // events_ is a heap
};
