#include "gas.h"

#include <cmath>
#include <random>

Scene makeGasScene(int count, std::uint32_t seed) {
    Scene scene;
    scene.name = "benchmark gas";
    scene.settings.gravity = {0.0, 0.0};
    scene.settings.bounciness = 1.0;
    scene.settings.dt = 1.0 / 60.0;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    scene.bounds = {{0.0, 0.0}, {static_cast<double>(side), static_cast<double>(side)}};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        const double angle = 2.0 * M_PI * unit(rng);
        const double speed = 3.0 * unit(rng);
        BlockDef b;
        b.position = {i % side + 0.5, i / side + 0.5};
        b.size = {0.5, 0.5};
        b.velocity = {speed * std::cos(angle), speed * std::sin(angle)};
        scene.blocks.push_back(b);
    }
    return scene;
}

World makeGas(int count, Method method, std::uint32_t seed) {
    World world = makeWorld(makeGasScene(count, seed));
    world.settings.method = method;
    world.settings.measureOverlap = false;
    return world;
}

World makeStorm(std::uint32_t seed) {
    Scene scene;
    scene.name = "event storm";
    scene.settings.gravity = {0.0, 0.0};
    scene.settings.bounciness = 1.0;
    scene.settings.dt = 1.0 / 60.0;
    scene.bounds = {{0.0, 0.0}, {20.0, 12.0}};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int columns = 40, rows = 25;
    for (int i = 0; i < columns * rows; ++i) {
        const double speed = 1e9 * std::sqrt(unit(rng));
        const double angle = 2.0 * M_PI * unit(rng);
        BlockDef b;
        b.position = {(i % columns + 0.5) * 20.0 / columns, (i / columns + 0.5) * 12.0 / rows};
        b.size = {0.25, 0.25};
        b.velocity = {speed * std::cos(angle), speed * std::sin(angle)};
        scene.blocks.push_back(b);
    }
    World world = makeWorld(scene);
    world.settings.method = Method::Perfect;
    world.settings.measureOverlap = false;
    return world;
}
