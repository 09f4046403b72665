// Chipmunk 7 as a peer on a scene: blocks with infinite moment (no rotation), the scene's
// settings as the peers take them (PeerUse, peers.h: gravity, friction, restitution C, where
// Chipmunk multiplies the two shapes' elasticities, so each shape gets sqrt(C)), the scene's dt
// with Chipmunk's default 10 iterations; walls as four static segments.
//
// Friction: Chipmunk multiplies the two shapes' friction, u = u1·u2. So each shape gets its face's
// factor (frictionFactor, world.h) of the engine's mu for its face (faceFriction: a block's own or
// the world's, the walls the world's), and every pair's mu is the engine's mixedFriction.
#include "peers.h"

#include <chipmunk/chipmunk.h>

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

class ChipmunkSimulation : public PeerSimulation {
  public:
    ChipmunkSimulation(const Scene& scene, double dt, int substeps)
        : PeerSimulation(scene, dt, substeps), space_(newSpaceQuietly()) {
        cpSpaceSetGravity(space_, cpv(settings().gravity.x, settings().gravity.y));
        const double elasticity = std::sqrt(settings().bounciness);
        const double world = settings().friction;
        const Vec2 lo = bounds_.min, hi = bounds_.max;
        const Vec2 corners[] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
        for (int k = 0; k < 4; ++k) {
            const Vec2 a = corners[k], b = corners[(k + 1) % 4];
            cpBody* ground = cpSpaceGetStaticBody(space_);
            addShape(cpSegmentShapeNew(ground, cpv(a.x, a.y), cpv(b.x, b.y), 0.0), elasticity,
                     frictionFactor(world));
        }
        for (const BlockDef& def : scene.blocks) {
            cpBody* body = def.kind == BodyKind::Dynamic     ? cpBodyNew(def.mass, INFINITY)
                           : def.kind == BodyKind::Kinematic ? cpBodyNewKinematic()
                                                             : cpBodyNewStatic();
            cpSpaceAddBody(space_, body);
            cpBodySetPosition(body, cpv(def.position.x, def.position.y));
            if (def.kind != BodyKind::Static)
                cpBodySetVelocity(body, cpv(def.velocity.x, def.velocity.y));
            addShape(cpBoxShapeNew(body, def.size.x, def.size.y, 0.0), elasticity,
                     frictionFactor(faceFriction(def.friction, world)));
            bodies_.push_back(body);
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

  private:
    void advance(double h) override { cpSpaceStep(space_, h); }
    Vec2 position(std::size_t i) const override {
        const cpVect p = cpBodyGetPosition(bodies_[i]);
        return {p.x, p.y};
    }
    Vec2 velocity(std::size_t i) const override {
        const cpVect v = cpBodyGetVelocity(bodies_[i]);
        return {v.x, v.y};
    }
    void addShape(cpShape* shape, double elasticity, double friction) {
        cpShapeSetElasticity(shape, elasticity);
        cpShapeSetFriction(shape, friction);
        cpSpaceAddShape(space_, shape);
        shapes_.push_back(shape);
    }

    cpSpace* space_;
    std::vector<cpShape*> shapes_;
    std::vector<cpBody*> bodies_;
};

} // namespace

std::unique_ptr<Simulation> makeChipmunkSimulation(const Scene& scene, double dt, int substeps) {
    return std::make_unique<ChipmunkSimulation>(scene, dt, substeps);
}
