// Box2D 2.4 on the same gas as the engine benchmark: fixed rotation, zero friction,
// restitution 1, dt 1/60, 8 velocity and 3 position iterations (the peer figures in NOTES-deps).
#include "gas.h"

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <memory>

namespace {

std::unique_ptr<b2World> makeBox2dGas(int count, double* kineticEnergy) {
    const World gas = makeGas(count, Method::MoveAndCorrect);
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
    // The four walls as one static body with four thin boxes just outside the bounds.
    b2BodyDef wallDef;
    b2Body* walls = world->CreateBody(&wallDef);
    const float w = static_cast<float>(gas.bounds.max.x), h = static_cast<float>(gas.bounds.max.y);
    const float t = 1.0f;
    b2PolygonShape shape;
    shape.SetAsBox(t, h / 2 + t, b2Vec2(-t, h / 2), 0.0f);
    walls->CreateFixture(&shape, 0.0f);
    shape.SetAsBox(t, h / 2 + t, b2Vec2(w + t, h / 2), 0.0f);
    walls->CreateFixture(&shape, 0.0f);
    shape.SetAsBox(w / 2 + t, t, b2Vec2(w / 2, -t), 0.0f);
    walls->CreateFixture(&shape, 0.0f);
    shape.SetAsBox(w / 2 + t, t, b2Vec2(w / 2, h + t), 0.0f);
    walls->CreateFixture(&shape, 0.0f);

    *kineticEnergy = 0.0;
    for (const Block& b : gas.blocks) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.fixedRotation = true;
        def.position.Set(static_cast<float>(b.position.x), static_cast<float>(b.position.y));
        def.linearVelocity.Set(static_cast<float>(b.velocity.x), static_cast<float>(b.velocity.y));
        b2Body* body = world->CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(b.size.x / 2), static_cast<float>(b.size.y / 2));
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.density = static_cast<float>(b.mass / (b.size.x * b.size.y));
        fixture.friction = 0.0f;
        fixture.restitution = 1.0f;
        body->CreateFixture(&fixture);
        *kineticEnergy += 0.5 * b.mass * lengthSquared(b.velocity);
    }
    return world;
}

double box2dKineticEnergy(b2World& world) {
    double e = 0.0;
    for (b2Body* b = world.GetBodyList(); b; b = b->GetNext()) {
        const b2Vec2 v = b->GetLinearVelocity();
        e += 0.5 * b->GetMass() * (v.x * v.x + v.y * v.y);
    }
    return e;
}

void BM_Box2D(benchmark::State& state) {
    double startEnergy = 0.0;
    auto world = makeBox2dGas(static_cast<int>(state.range(0)), &startEnergy);
    for (int i = 0; i < 30; ++i) world->Step(1.0f / 60.0f, 8, 3);
    for (auto _ : state) world->Step(1.0f / 60.0f, 8, 3);
    // Accuracy alongside speed: the relative change of kinetic energy over the run.
    state.counters["energy_drift"] = (box2dKineticEnergy(*world) - startEnergy) / startEnergy;
}

} // namespace

BENCHMARK(BM_Box2D)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);
