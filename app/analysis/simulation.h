// A simulation to measure: the engine under one method, or a peer engine (Box2D) on the same
// scene. Both step a frame at a time and report the blocks' state in the scene's order.
#pragma once

#include "scene.h"

#include <memory>
#include <string>
#include <vector>

class Simulation {
  public:
    virtual ~Simulation() = default;
    // Advances one frame; returns the milliseconds spent stepping.
    virtual double step() = 0;
    // Positions and velocities of the blocks now, in the scene's order.
    virtual const std::vector<Block>& blocks() = 0;
    // Largest overlap (m) between blocks or with the walls now (or seen during the last step).
    virtual double penetration() = 0;
    // Event-cap hits in the last step (0 for engines without a cap).
    virtual int eventCapHits() const { return 0; }
    // Collisions resolved in the last step (-1 when the engine does not say).
    virtual int collisions() const { return -1; }
    virtual double time() const = 0; // s simulated
};

// The engine on `scene` with the given method, dt and substeps.
std::unique_ptr<Simulation> makeEngineSimulation(const Scene& scene, Method method, double dt,
                                                 int substeps);

// Peers available in this build ("box2d" when Box2D 2.4 was found), and a factory for them;
// nullptr for an unknown name.
std::vector<std::string> peerNames();
std::unique_ptr<Simulation> makePeerSimulation(const std::string& peer, const Scene& scene,
                                               double dt, int substeps);
