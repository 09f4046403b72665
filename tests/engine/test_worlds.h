// Small builders for the engine tests: worlds with chosen settings, single blocks, and random
// non-overlapping "gas" scenes from a fixed seed (no clock, no file).
#pragma once

#include "world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace test_worlds {

inline World makeWorld(Method method, Vec2 gravity = {0.0, 0.0}, double bounciness = 1.0,
                       Bounds bounds = Bounds{}) {
    World world;
    world.settings.method = method;
    world.settings.gravity = gravity;
    world.settings.bounciness = bounciness;
    world.bounds = bounds;
    return world;
}

// Adds a block and returns its index. Static and kinematic blocks get infinite mass.
inline int addBlock(World& world, Vec2 position, Vec2 size, Vec2 velocity = {}, double mass = 1.0,
                    BodyKind kind = BodyKind::Dynamic) {
    Block b;
    b.position = position;
    b.size = size;
    b.velocity = velocity;
    b.kind = kind;
    b.mass = kind == BodyKind::Dynamic ? mass : kInfiniteMass;
    world.blocks.push_back(b);
    return static_cast<int>(world.blocks.size()) - 1;
}

struct GasOptions {
    Vec2 min{0.0, 0.0}; // m, region filled with blocks
    Vec2 max{20.0, 12.0};
    int count = 200;
    double minFill = 0.4; // block size as a fraction of its grid cell
    double maxFill = 0.8;
    double maxSpeed = 5.0; // m/s, per component
    double minMass = 0.5;  // kg
    double maxMass = 2.0;
    std::uint64_t seed = 1;
};

// A grid of at least `count` cells, about square, over a region `span` wide and high: block k
// goes into the cell of column k % columns and row k / columns (addGas, the robustness soak).
struct CellGrid {
    int columns = 1;
    int rows = 1;
    Vec2 cell; // m
};
inline CellGrid cellGridFor(int count, Vec2 span) {
    CellGrid g;
    g.columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(count * span.x / span.y))));
    g.rows = (count + g.columns - 1) / g.columns;
    g.cell = Vec2{span.x / g.columns, span.y / g.rows};
    return g;
}

// One block per cell of a grid over the region, at a random place inside its cell: the blocks
// never overlap each other and never stick out of the region.
inline void addGas(World& world, const GasOptions& o) {
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const CellGrid grid = cellGridFor(o.count, o.max - o.min);
    const Vec2 cell = grid.cell;
    for (int k = 0; k < o.count; ++k) {
        const int cx = k % grid.columns, cy = k / grid.columns;
        const double fill = o.minFill + (o.maxFill - o.minFill) * unit(rng);
        const Vec2 size{cell.x * fill, cell.y * (o.minFill + (o.maxFill - o.minFill) * unit(rng))};
        const Vec2 slack = cell - size;
        const Vec2 position{o.min.x + cx * cell.x + size.x * 0.5 + slack.x * unit(rng),
                            o.min.y + cy * cell.y + size.y * 0.5 + slack.y * unit(rng)};
        const Vec2 velocity{o.maxSpeed * (2.0 * unit(rng) - 1.0),
                            o.maxSpeed * (2.0 * unit(rng) - 1.0)};
        const double mass = o.minMass + (o.maxMass - o.minMass) * unit(rng);
        addBlock(world, position, size, velocity, mass);
    }
}

// A gas of `count` blocks (addGas's defaults) filling a closed 20 m x 20 m box.
inline World gasInBox(Method method, Vec2 gravity, double bounciness, std::uint64_t seed,
                      int count) {
    World world = makeWorld(method, gravity, bounciness, Bounds{{0.0, 0.0}, {20.0, 20.0}});
    GasOptions gas;
    gas.min = {0.0, 0.0};
    gas.max = {20.0, 20.0};
    gas.count = count;
    gas.seed = seed;
    addGas(world, gas);
    return world;
}

// Σ m·|v| over the dynamic blocks (kg·m/s): the scale against which momentum errors are relative
// (the total momentum itself may be near zero).
inline double momentumScale(const World& world) {
    double s = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) s += b.mass * length(b.velocity);
    return s;
}

// Test names for a parameterized test over Method: the method's name in camel case
// ("move-and-correct" is MoveAndCorrect; "-" is not allowed in test names).
inline std::string methodTestName(Method method) {
    std::string name;
    bool wordStart = true;
    for (const char* c = methodName(method); *c; ++c) {
        if (*c == '-') {
            wordStart = true;
            continue;
        }
        name += wordStart ? static_cast<char>(std::toupper(static_cast<unsigned char>(*c))) : *c;
        wordStart = false;
    }
    return name;
}

// Every method of the engine's enum (Method::Count of them, in its order) and their test names:
// INSTANTIATE_TEST_SUITE_P(Methods, Suite, test_worlds::everyMethod(),
// test_worlds::methodParamName)
inline ::testing::internal::ParamGenerator<Method> everyMethod() {
    std::vector<Method> methods;
    for (int m = 0; m < static_cast<int>(Method::Count); ++m)
        methods.push_back(static_cast<Method>(m));
    return ::testing::ValuesIn(methods);
}
inline std::string methodParamName(const ::testing::TestParamInfo<Method>& info) {
    return methodTestName(info.param);
}

} // namespace test_worlds
