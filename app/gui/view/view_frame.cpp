#include "view_frame.h"

#include "text_format.h"

CentreOfMass centreOfMass(const World& world) {
    CentreOfMass c;
    Vec2 mp, mv;
    for (const Block& b : world.blocks) {
        if (!b.isDynamic()) continue;
        c.mass += b.mass;
        mp += b.position * b.mass;
        mv += b.velocity * b.mass;
    }
    if (!(c.mass > 0.0)) return c;
    c.valid = true;
    c.position = mp / c.mass;
    c.velocity = mv / c.mass;
    return c;
}

Vec2 frameVelocity(const World& world, ViewFrame frame) {
    if (frame != ViewFrame::CentreOfMass) return {};
    const CentreOfMass c = centreOfMass(world);
    return c.valid ? c.velocity : Vec2{};
}

std::string frameVelocityLabel(const std::string& blockName, Vec2 velocity, ViewFrame frame) {
    const std::string symbol =
        (frame == ViewFrame::CentreOfMass ? "w" : "v") + formulaSymbol(baseBlockName(blockName));
    const double scale = length(velocity);
    if (isRoundingNoise(velocity.y, scale))
        return symbol + " = " + formatQuantity(velocity.x, "m/s");
    return symbol + " = (" + formatNumber(velocity.x, scale) + ", " +
           formatNumber(velocity.y, scale) + ") m/s";
}

void anchorFrameCamera(FrameCamera& follow, const World& world) {
    const CentreOfMass c = centreOfMass(world);
    follow.anchored = c.valid;
    follow.anchor = c.position;
    follow.last = c.position;
}

Vec2 followShift(FrameCamera& follow, const World& world, ViewFrame frame, bool fitted) {
    if (frame != ViewFrame::CentreOfMass) return {};
    const CentreOfMass c = centreOfMass(world);
    if (!c.valid) return {};
    if (!follow.anchored) anchorFrameCamera(follow, world);
    const Vec2 shift = fitted ? c.position - follow.anchor : c.position - follow.last;
    follow.last = c.position;
    return shift;
}
