// What sandbox-cli's commands print a vector as: [x, y] in JSON, (x, y) in text.
#pragma once

#include "vec2.h"

#include <nlohmann/json.hpp>

#include <ostream>

inline nlohmann::ordered_json vecJson(Vec2 v) {
    return {v.x, v.y};
}

inline std::ostream& operator<<(std::ostream& out, Vec2 v) {
    return out << "(" << v.x << ", " << v.y << ")";
}
