#include "gas.h"

#include <cmath>
#include <random>

World makeGas(int count, Method method, std::uint32_t seed) {
    World world;
    world.settings.gravity = {0.0, 0.0};
    world.settings.bounciness = 1.0;
    world.settings.dt = 1.0 / 60.0;
    world.settings.method = method;
    world.settings.measureOverlap = false;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    world.bounds = {{0.0, 0.0}, {static_cast<double>(side), static_cast<double>(side)}};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
        const double angle = 2.0 * M_PI * unit(rng);
        const double speed = 3.0 * unit(rng);
        Block b;
        b.position = {i % side + 0.5, i / side + 0.5};
        b.size = {0.5, 0.5};
        b.velocity = {speed * std::cos(angle), speed * std::sin(angle)};
        b.mass = 1.0;
        world.blocks.push_back(b);
    }
    return world;
}
