// A block as a scene file describes it (docs/scene-format.md): its own header, below both the
// scene (scene.h) and the settings table's readers (settings_table.cpp), which need only this.
#pragma once

#include "vec2.h"
#include "world.h"

#include <string>

struct BlockDef {
    std::string name;    // optional in the file ("" when absent)
    Vec2 position;       // m
    Vec2 size{1.0, 1.0}; // m
    Vec2 velocity;       // m/s
    double mass = 1.0;   // kg (dynamic only)
    Vec2 force;          // N, constant (dynamic only): a thruster, a = F/m
    BodyKind kind = BodyKind::Dynamic;
    std::string color; // "#rrggbb", optional ("" when absent)

    bool operator==(const BlockDef& o) const; // as a scene file holds it (scene_save.cpp)
};
