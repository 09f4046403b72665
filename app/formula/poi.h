// Point of impact for one block over one frame (lecture, "Point of Impact (POI) Calculation"):
// from the old position and the frame's velocity, the new position the block would reach without
// the collision, the time of impact t = a/b from the engine's timeOfImpact, the ghost at
// POI = oldPosition + t·velocity, and the "crooked" result of simply moving back along the
// collision axis only. Pure logic.
#pragma once

#include "world.h"

#include <string>
#include <vector>

struct PoiView {
    bool valid = false;
    int block = -1;
    int other = 0;           // block index, or a Wall (negative)
    int axis = 0;            // 0 = x, 1 = y
    double frameStart = 0.0; // s, world time at the start of the frame
    double dt = 0.0;         // s
    Vec2 size;
    Vec2 oldPosition; // start of the frame
    Vec2 newPosition; // end of the frame had nothing been in the way
    Vec2 ghost;       // at the point of impact
    Vec2 crooked;     // new position moved back along the collision axis only
    Vec2 velocity;    // m/s during the frame (gravity applied first)
    double t = 0.0;   // time of impact as a fraction of the frame
    double a = 0.0;   // m, how far the facing sides close along the axis until the impact
    double b = 0.0;   // m, how far they close over the whole frame (relative speed · dt)
};

// The point of impact of `block` in the frame that started from `before` (the blocks at the
// start of the frame) under `settings`; invalid when the block hits nothing during the frame.
PoiView computePoi(const std::vector<Block>& before, const Bounds& bounds,
                   const WorldSettings& settings, double frameStart, int block);

// The time of impact as the lecture writes it, with as many digits as make it hold as printed:
// "t = a/b = 0.15/1.4 = 0.107 of the frame   (a, b: m along y)"; without `units`, in fewer
// words (a narrow scene's plate: "t = a/b = 0.15/1.4 = 0.107 of frame").
std::string poiEquation(const PoiView& p, bool units = true);
