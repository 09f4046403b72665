// Where the perfect method finds the impacts it predicts (perfect.cpp). Plainly: each block's path
// for the rest of the substep is registered in one PathIndex, and a block whose velocity changed
// is tested against every block whose path meets its own. In a storm (blocks crossing the world
// many times per substep) through windows of time instead (impact_search.cpp, "Windows"): the same
// impacts in the same order, found with far fewer tests. The loop sees only this interface, as
// the rest rule sees only the PathIndex.
#pragma once

#include "path_index.h"
#include "substep_timeline.h"

#include <cstdint>
#include <vector>

class ImpactSearch {
  public:
    ImpactSearch(SubstepContext& ctx, PerfectScratch& scratch, SubstepTimeline& timeline);

    // The paths: where the rest rule finds a cluster's neighbours.
    const BlockFinder& paths() const { return paths_; }

    // Registers every block's path over the substep and predicts the first impacts (through
    // windows when the substep's travel calls for them); then the timeline's queue starts.
    void start();
    // Windows: if a window ends (a horizon) no later than the earliest predicted impact, registers
    // its block's next window, whose impacts may come before that one, and returns true. Nothing
    // is resolved or counted at a horizon. The plain search has none.
    bool passHorizon() { return windowed_ && passHorizonOfWindows(); }
    // The resolver has brought block i to a later time without changing its velocity.
    void moved(int i) {
        if (windowed_) noteMotion(i);
    }
    // An event at `now` changed the velocities of `changed` (sorted, each once, restamped): their
    // paths grow to cover their new trajectories, and their impacts are predicted again.
    void changed(const std::vector<int>& changed, double now);

  private:
    void registerPaths();
    void predictWalls(int i, double now, const Aabb& path);
    void predictPair(int i, int j, double now);
    void predict(int i, double now);
    void predictStops(int i, double now);
    // Windows (see impact_search.cpp).
    bool useWindows();
    void startWindows();
    bool passHorizonOfWindows();
    void noteMotion(int i);
    void changedInWindows(const std::vector<int>& changed, double now);
    void registerWindow(int i, double start, std::uint32_t batch, bool build = false);
    Aabb windowBox(int i, double start, double end) const;
    void searchWindow(int i, std::uint32_t batch);
    void lookAtPair(int x, int y);
    void predictPairFrom(int i, const Motion& mi, int j, const Motion& mj, double now);
    const Motion& motionAsOf(int i, double t) const;

    SubstepContext& ctx_;
    std::vector<Block>& blocks_;
    SubstepTimeline& timeline_;
    PathIndex paths_;
    Aabb wallsInside_; // the bounds shrunk by far more than rounding (see start())
    // Windows.
    PerfectScratch& w_;
    PathIndex windows_;         // each block's current window
    bool windowed_ = false;     // this substep finds its impacts through windows
    double windowTravel_ = 0.0; // m: the first window's travel
    std::uint32_t serial_ = 0;  // events that changed a velocity so far
    std::uint32_t batch_ = 0;   // window registrations so far (one batch at a change)
};
