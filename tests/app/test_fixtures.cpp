#include "test_fixtures.h"

#include <cmath>
#include <utility>

BlockDef testBlock(const std::string& name, Vec2 position, Vec2 size, double mass) {
    BlockDef b;
    b.name = name, b.position = position, b.size = size, b.mass = mass;
    return b;
}

BlockDef staticBlock(const std::string& name, Vec2 position, Vec2 size) {
    BlockDef b = testBlock(name, position, size);
    b.kind = BodyKind::Static;
    return b;
}

Scene weightlessScene(const std::string& name, std::vector<BlockDef> blocks) {
    Scene scene;
    scene.name = name;
    scene.settings.gravity = Vec2{0.0, 0.0};
    scene.blocks = std::move(blocks);
    return scene;
}

CollisionRecord rightWallHit(int block, double mass) {
    CollisionRecord r;
    r.time = 1.5, r.block = block, r.other = kWallRight, r.axis = 0;
    r.m1 = mass, r.m2 = INFINITY;
    r.v1 = 4.0, r.v2 = 0.0, r.u = 0.0, r.C = 0.5, r.v1After = -2.0;
    return r;
}

ParsedOptions parseCommandLine(const std::vector<const char*>& args) {
    return parseOptions(static_cast<int>(args.size()), args.data());
}
