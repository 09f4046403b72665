// The peer engines behind makePeerSimulation, each in its own file and built only when its
// Debian package is installed (libbox2d-dev, libchipmunk-dev), and what they share.
#pragma once

#include "settings_table.h"
#include "simulation.h"

#include <optional>
#include <string>
#include <vector>

// What the peers make of each world key of the settings table (settings_table::worldKeys()):
// Set, the peer is set up with the scene's value; Caller, the run gives it (dt and substeps: the
// tradeoff's frame rates); OwnSolver, a choice of how the sandbox solves (method, integrator,
// resolve, mistakes, its engine-only rows) that a peer makes its own way; Lacks, the peer has
// nothing for it, and a scene that sets it runs without it (settingsPeersLack).
enum class PeerUse { Set, Caller, OwnSolver, Lacks };
// The row's use in peers.cpp's list; none for a key the list does not have yet (a new world key:
// the peers refuse to run, and PeerKeys.* fails, until it is placed there).
std::optional<PeerUse> peerUse(const settings_table::WorldKey& row);
// The settings of `s` a peer runs without: "drag 0.5 kg/m³" for each Lacks row whose value is not
// the default.
std::vector<std::string> settingsPeersLack(const WorldSettings& s);

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
    // The scene's settings as the peers take them: its Set rows, the defaults elsewhere.
    const WorldSettings& settings() const { return settings_; }
    virtual void advance(double h) = 0; // one substep of h seconds in the peer
    virtual Vec2 position(std::size_t block) const = 0;
    virtual Vec2 velocity(std::size_t block) const = 0;
    void refresh(); // reads every block back from the peer; call at the end of construction

    Bounds bounds_;

  private:
    WorldSettings settings_;
    std::vector<Block> blocks_;
    double dt_;
    int substeps_;
    double time_ = 0.0;
};

std::unique_ptr<Simulation> makeBox2dSimulation(const Scene& scene, double dt, int substeps);
std::unique_ptr<Simulation> makeChipmunkSimulation(const Scene& scene, double dt, int substeps);
