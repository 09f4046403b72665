// Box2D 2.4 as a peer on a scene: fixed rotation, the scene's settings as the peers take them
// (PeerUse, peers.h: gravity, friction, restitution C), the scene's dt with 8 velocity and 3
// position iterations; walls as four static boxes outside the bounds.
//
// Friction: Box2D mixes a contact's friction as the geometric mean sqrt(f1·f2) of its two
// fixtures' (b2MixFriction), the engine's rule (mixedFriction, world.h). So each fixture gets the
// engine's mu for its face (faceFriction: a block's own or the world's, the walls the world's),
// and every pair's mu is the engine's.
#include "peers.h"

#include <box2d/box2d.h>

namespace {

b2Vec2 toB2(Vec2 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y)};
}

class Box2dSimulation : public PeerSimulation {
  public:
    Box2dSimulation(const Scene& scene, double dt, int substeps)
        : PeerSimulation(scene, dt, substeps), world_(toB2(settings().gravity)) {
        const double world = settings().friction;
        addWalls(world);
        for (const BlockDef& def : scene.blocks)
            addBlock(def, settings().bounciness, faceFriction(def.friction, world));
        refresh();
    }

  private:
    void advance(double h) override { world_.Step(static_cast<float>(h), 8, 3); }
    Vec2 position(std::size_t i) const override {
        const b2Vec2 p = bodies_[i]->GetPosition();
        return {p.x, p.y};
    }
    Vec2 velocity(std::size_t i) const override {
        const b2Vec2 v = bodies_[i]->GetLinearVelocity();
        return {v.x, v.y};
    }

    void addWalls(double friction) {
        b2BodyDef def;
        b2Body* walls = world_.CreateBody(&def);
        const Vec2 c = (bounds_.min + bounds_.max) * 0.5, half = (bounds_.max - bounds_.min) * 0.5;
        const double t = 1.0; // m, wall thickness (outside the bounds)
        auto box = [&](double hx, double hy, double cx, double cy) {
            b2PolygonShape shape;
            shape.SetAsBox(static_cast<float>(hx), static_cast<float>(hy), toB2({cx, cy}), 0.0f);
            b2FixtureDef fixture;
            fixture.shape = &shape;
            fixture.friction = static_cast<float>(friction);
            walls->CreateFixture(&fixture);
        };
        box(t, half.y + t, bounds_.min.x - t, c.y);
        box(t, half.y + t, bounds_.max.x + t, c.y);
        box(half.x + t, t, c.x, bounds_.min.y - t);
        box(half.x + t, t, c.x, bounds_.max.y + t);
    }
    void addBlock(const BlockDef& def, double bounciness, double friction) {
        b2BodyDef bodyDef;
        bodyDef.type = def.kind == BodyKind::Dynamic     ? b2_dynamicBody
                       : def.kind == BodyKind::Kinematic ? b2_kinematicBody
                                                         : b2_staticBody;
        bodyDef.fixedRotation = true;
        bodyDef.position = toB2(def.position);
        if (def.kind != BodyKind::Static) bodyDef.linearVelocity = toB2(def.velocity);
        b2Body* body = world_.CreateBody(&bodyDef);
        b2PolygonShape shape;
        shape.SetAsBox(static_cast<float>(def.size.x / 2), static_cast<float>(def.size.y / 2));
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = static_cast<float>(def.mass / (def.size.x * def.size.y));
        fixture.friction = static_cast<float>(friction);
        fixture.restitution = static_cast<float>(bounciness);
        body->CreateFixture(&fixture);
        bodies_.push_back(body);
    }

    b2World world_;
    std::vector<b2Body*> bodies_;
};

} // namespace

std::unique_ptr<Simulation> makeBox2dSimulation(const Scene& scene, double dt, int substeps) {
    return std::make_unique<Box2dSimulation>(scene, dt, substeps);
}
