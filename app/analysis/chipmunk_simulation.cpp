// Chipmunk 7 as a peer on a scene: blocks with infinite moment (no rotation), zero friction,
// restitution C (Chipmunk multiplies the two shapes' elasticities, so each shape gets sqrt(C)),
// the scene's dt with Chipmunk's default 10 iterations; walls as four static segments.
#include "peers.h"

#include "collision.h"

#include <chipmunk/chipmunk.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace {

// Debian's Chipmunk is built with its debug messages on: the first cpSpaceNew prints a banner to
// standard output, which would land in the middle of sandbox-cli's output. Create the first space
// with standard output pointed at /dev/null.
cpSpace* newSpaceQuietly() {
    static bool bannerShown = false;
    if (bannerShown) return cpSpaceNew();
    bannerShown = true;
    std::fflush(stdout);
    const int saved = dup(STDOUT_FILENO);
    const int devNull = open("/dev/null", O_WRONLY);
    if (saved >= 0 && devNull >= 0) dup2(devNull, STDOUT_FILENO);
    cpSpace* space = cpSpaceNew();
    std::fflush(stdout);
    if (saved >= 0) dup2(saved, STDOUT_FILENO);
    if (saved >= 0) close(saved);
    if (devNull >= 0) close(devNull);
    return space;
}

class ChipmunkSimulation : public Simulation {
  public:
    ChipmunkSimulation(const Scene& scene, double dt, int substeps)
        : space_(newSpaceQuietly()), bounds_(scene.bounds), dt_(dt), substeps_(substeps) {
        cpSpaceSetGravity(space_, cpv(scene.settings.gravity.x, scene.settings.gravity.y));
        const double elasticity = std::sqrt(scene.settings.bounciness);
        const Vec2 lo = bounds_.min, hi = bounds_.max;
        const Vec2 corners[] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
        for (int k = 0; k < 4; ++k) {
            const Vec2 a = corners[k], b = corners[(k + 1) % 4];
            addShape(
                cpSegmentShapeNew(cpSpaceGetStaticBody(space_), cpv(a.x, a.y), cpv(b.x, b.y), 0.0),
                elasticity);
        }
        for (const BlockDef& def : scene.blocks) {
            cpBody* body = def.kind == BodyKind::Dynamic     ? cpBodyNew(def.mass, INFINITY)
                           : def.kind == BodyKind::Kinematic ? cpBodyNewKinematic()
                                                             : cpBodyNewStatic();
            cpSpaceAddBody(space_, body);
            cpBodySetPosition(body, cpv(def.position.x, def.position.y));
            if (def.kind != BodyKind::Static)
                cpBodySetVelocity(body, cpv(def.velocity.x, def.velocity.y));
            addShape(cpBoxShapeNew(body, def.size.x, def.size.y, 0.0), elasticity);
            bodies_.push_back(body);
            Block b;
            b.size = def.size;
            b.kind = def.kind;
            b.mass = def.kind == BodyKind::Dynamic ? def.mass : kInfiniteMass;
            blocks_.push_back(b);
        }
        refresh();
    }
    ~ChipmunkSimulation() override {
        for (cpShape* s : shapes_) {
            cpSpaceRemoveShape(space_, s);
            cpShapeFree(s);
        }
        for (cpBody* b : bodies_) {
            cpSpaceRemoveBody(space_, b);
            cpBodyFree(b);
        }
        cpSpaceFree(space_);
    }
    ChipmunkSimulation(const ChipmunkSimulation&) = delete;
    ChipmunkSimulation& operator=(const ChipmunkSimulation&) = delete;

    double step() override {
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < substeps_; ++k) cpSpaceStep(space_, dt_ / substeps_);
        const auto end = std::chrono::steady_clock::now();
        time_ += dt_;
        refresh();
        return std::chrono::duration<double, std::milli>(end - start).count();
    }
    const std::vector<Block>& blocks() override { return blocks_; }
    double penetration() override { return bruteForcePenetration(blocks_, bounds_); }
    double time() const override { return time_; }

  private:
    void addShape(cpShape* shape, double elasticity) {
        cpShapeSetElasticity(shape, elasticity);
        cpShapeSetFriction(shape, 0.0);
        cpSpaceAddShape(space_, shape);
        shapes_.push_back(shape);
    }
    void refresh() {
        for (size_t i = 0; i < bodies_.size(); ++i) {
            const cpVect p = cpBodyGetPosition(bodies_[i]), v = cpBodyGetVelocity(bodies_[i]);
            blocks_[i].position = {p.x, p.y};
            blocks_[i].velocity = {v.x, v.y};
        }
    }

    cpSpace* space_;
    Bounds bounds_;
    double dt_;
    int substeps_;
    double time_ = 0.0;
    std::vector<cpShape*> shapes_;
    std::vector<cpBody*> bodies_;
    std::vector<Block> blocks_;
};

} // namespace

std::unique_ptr<Simulation> makeChipmunkSimulation(const Scene& scene, double dt, int substeps) {
    return std::make_unique<ChipmunkSimulation>(scene, dt, substeps);
}
