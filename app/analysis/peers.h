// The peer engines behind makePeerSimulation, each in its own file and built only when its
// Debian package is installed (libbox2d-dev, libchipmunk-dev), and what they share.
#pragma once

#include "simulation.h"

// A peer seen through Simulation: the blocks' state in scene order (read back from the peer after
// every step), the bounds, the clock, and the timing of the peer's own stepping. A peer supplies
// one substep and each block's position and velocity.
class PeerSimulation : public Simulation {
  public:
    PeerSimulation(const Scene& scene, double dt, int substeps);
    double step() final;
    const std::vector<Block>& blocks() final { return blocks_; }
    double penetration() final;
    double time() const final { return time_; }

  protected:
    virtual void advance(double h) = 0; // one substep of h seconds in the peer
    virtual Vec2 position(std::size_t block) const = 0;
    virtual Vec2 velocity(std::size_t block) const = 0;
    void refresh(); // reads every block back from the peer; call at the end of construction

    Bounds bounds_;

  private:
    std::vector<Block> blocks_;
    double dt_;
    int substeps_;
    double time_ = 0.0;
};

std::unique_ptr<Simulation> makeBox2dSimulation(const Scene& scene, double dt, int substeps);
std::unique_ptr<Simulation> makeChipmunkSimulation(const Scene& scene, double dt, int substeps);
