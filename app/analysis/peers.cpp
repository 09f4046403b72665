// The peers' common part (PeerSimulation) and the factory over the peers built in.
#include "peers.h"

#include "collision.h"
#include "input_limits.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace {

// Every world key and what the peers make of it (PeerUse). A new key goes here too.
struct PeerKey {
    const char* key;
    PeerUse use;
};
const PeerKey kPeerKeys[] = {
    {"gravity", PeerUse::Set},
    {"bounciness", PeerUse::Set},
    {"friction", PeerUse::Set},
    {"dt", PeerUse::Caller},
    {"substeps", PeerUse::Caller},
    {"method", PeerUse::OwnSolver},
    {"resolve", PeerUse::OwnSolver},
    {"integrator", PeerUse::OwnSolver},
    {"mistakes", PeerUse::OwnSolver},
    {"drag", PeerUse::Lacks},
    {"rest_speed", PeerUse::OwnSolver},
    {"event_cap", PeerUse::OwnSolver},
    {"measure_overlap", PeerUse::OwnSolver},
};

} // namespace

std::optional<PeerUse> peerUse(const settings_table::WorldKey& row) {
    for (const PeerKey& k : kPeerKeys)
        if (std::string(k.key) == row.key) return k.use;
    return std::nullopt;
}

std::vector<std::string> settingsPeersLack(const WorldSettings& s) {
    const WorldSettings defaults = defaultWorldSettings();
    std::vector<std::string> lacked;
    for (const settings_table::WorldKey& row : settings_table::worldKeys())
        if (peerUse(row) == PeerUse::Lacks && !settings_table::same(row, s, defaults))
            lacked.push_back(std::string(row.key) + " " +
                             settings_table::shownValue(row, s, limits::formatNumber));
    return lacked;
}

std::vector<std::string> peerNames() {
    std::vector<std::string> names;
#ifdef SANDBOX_HAVE_BOX2D
    names.push_back("box2d");
#endif
#ifdef SANDBOX_HAVE_CHIPMUNK
    names.push_back("chipmunk");
#endif
    return names;
}

std::unique_ptr<Simulation> makePeerSimulation(const std::string& peer, const Scene& scene,
                                               double dt, int substeps) {
#ifdef SANDBOX_HAVE_BOX2D
    if (peer == "box2d") return makeBox2dSimulation(scene, dt, substeps);
#endif
#ifdef SANDBOX_HAVE_CHIPMUNK
    if (peer == "chipmunk") return makeChipmunkSimulation(scene, dt, substeps);
#endif
    (void)peer, (void)scene, (void)dt, (void)substeps; // unused when no peer is built
    return nullptr;
}

PeerSimulation::PeerSimulation(const Scene& scene, double dt, int substeps)
    : bounds_(scene.bounds), settings_(defaultWorldSettings()), dt_(dt), substeps_(substeps) {
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        const std::optional<PeerUse> use = peerUse(row);
        if (!use)
            throw std::logic_error(std::string("the peers do not say what they make of the world "
                                               "key \"") +
                                   row.key + "\" (app/analysis/peers.cpp)");
        if (*use == PeerUse::Set) settings_table::copy(row, scene.settings, settings_);
    }
    for (const BlockDef& def : scene.blocks) {
        Block b;
        b.size = def.size;
        b.kind = def.kind;
        b.mass = def.kind == BodyKind::Dynamic ? def.mass : kInfiniteMass;
        blocks_.push_back(b);
    }
}

double PeerSimulation::step() {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < substeps_; ++k) advance(dt_ / substeps_);
    const auto end = std::chrono::steady_clock::now();
    time_ += dt_;
    refresh();
    return std::chrono::duration<double, std::milli>(end - start).count();
}

void PeerSimulation::refresh() {
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        blocks_[i].position = position(i);
        blocks_[i].velocity = velocity(i);
    }
}

// Largest overlap (m) among the blocks and with the walls, pair by pair (peers are measured on
// small scenes only).
double PeerSimulation::penetration() {
    double deepest = 0.0;
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        const Aabb a = aabbOf(blocks_[i]);
        deepest = std::max(deepest, outsideDepth(a, bounds_));
        for (std::size_t j = i + 1; j < blocks_.size(); ++j)
            if (blocks_[i].isDynamic() || blocks_[j].isDynamic())
                deepest = std::max(deepest, ::penetration(a, aabbOf(blocks_[j])));
    }
    return deepest;
}
