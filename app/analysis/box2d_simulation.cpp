// Box2D 2.4 as a peer on a scene: fixed rotation, zero friction, restitution C, the scene's dt
// with 8 velocity and 3 position iterations; walls as four static boxes outside the bounds.
#include "peers.h"

#include "collision.h"

#include <box2d/box2d.h>

#include <chrono>

namespace {

class Box2dSimulation : public Simulation {
  public:
    Box2dSimulation(const Scene& scene, double dt, int substeps)
        : world_(b2Vec2(static_cast<float>(scene.settings.gravity.x),
                        static_cast<float>(scene.settings.gravity.y))),
          bounds_(scene.bounds), dt_(dt), substeps_(substeps) {
        addWalls();
        for (const BlockDef& def : scene.blocks) addBlock(def, scene.settings.bounciness);
        refresh();
    }

    double step() override {
        const auto start = std::chrono::steady_clock::now();
        const float h = static_cast<float>(dt_ / substeps_);
        for (int k = 0; k < substeps_; ++k) world_.Step(h, 8, 3);
        const auto end = std::chrono::steady_clock::now();
        time_ += dt_;
        refresh();
        return std::chrono::duration<double, std::milli>(end - start).count();
    }
    const std::vector<Block>& blocks() override { return blocks_; }
    double penetration() override { return bruteForcePenetration(blocks_, bounds_); }
    double time() const override { return time_; }

  private:
    void addWalls() {
        b2BodyDef def;
        b2Body* walls = world_.CreateBody(&def);
        const Vec2 c = (bounds_.min + bounds_.max) * 0.5, half = (bounds_.max - bounds_.min) * 0.5;
        const float t = 1.0f;
        auto box = [&](double hx, double hy, double cx, double cy) {
            b2PolygonShape shape;
            shape.SetAsBox(static_cast<float>(hx), static_cast<float>(hy),
                           b2Vec2(static_cast<float>(cx), static_cast<float>(cy)), 0.0f);
            walls->CreateFixture(&shape, 0.0f);
        };
        box(t, half.y + t, bounds_.min.x - t, c.y);
        box(t, half.y + t, bounds_.max.x + t, c.y);
        box(half.x + t, t, c.x, bounds_.min.y - t);
        box(half.x + t, t, c.x, bounds_.max.y + t);
    }
    void addBlock(const BlockDef& def, double bounciness) {
        b2BodyDef bodyDef;
        bodyDef.type = def.kind == BodyKind::Dynamic     ? b2_dynamicBody
                       : def.kind == BodyKind::Kinematic ? b2_kinematicBody
                                                         : b2_staticBody;
        bodyDef.fixedRotation = true;
        bodyDef.position.Set(static_cast<float>(def.position.x),
                             static_cast<float>(def.position.y));
        if (def.kind != BodyKind::Static)
            bodyDef.linearVelocity.Set(static_cast<float>(def.velocity.x),
                                       static_cast<float>(def.velocity.y));
        b2Body* body = world_.CreateBody(&bodyDef);
        b2PolygonShape shape;
        shape.SetAsBox(static_cast<float>(def.size.x / 2), static_cast<float>(def.size.y / 2));
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = static_cast<float>(def.mass / (def.size.x * def.size.y));
        fixture.friction = 0.0f;
        fixture.restitution = static_cast<float>(bounciness);
        body->CreateFixture(&fixture);
        bodies_.push_back(body);
        Block b;
        b.size = def.size;
        b.kind = def.kind;
        b.mass = def.kind == BodyKind::Dynamic ? def.mass : kInfiniteMass;
        blocks_.push_back(b);
    }
    void refresh() {
        for (size_t i = 0; i < bodies_.size(); ++i) {
            const b2Vec2 p = bodies_[i]->GetPosition(), v = bodies_[i]->GetLinearVelocity();
            blocks_[i].position = {p.x, p.y};
            blocks_[i].velocity = {v.x, v.y};
        }
    }

    b2World world_;
    Bounds bounds_;
    double dt_;
    int substeps_;
    double time_ = 0.0;
    std::vector<b2Body*> bodies_;
    std::vector<Block> blocks_;
};

} // namespace

std::unique_ptr<Simulation> makeBox2dSimulation(const Scene& scene, double dt, int substeps) {
    return std::make_unique<Box2dSimulation>(scene, dt, substeps);
}
