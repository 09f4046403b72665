// Shared by scene.cpp (error messages) and scene_save.cpp (writing): JSON values as text.
#pragma once

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

namespace scene_json {

// One value on one line; invalid UTF-8 (only possible in scenes built in code) is replaced.
// Doubles print in the shortest form that reads back to the same bits.
inline std::string dumpValue(const nlohmann::json& value) {
    return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

inline std::string numberList(std::initializer_list<double> xs) {
    std::string out = "[";
    for (double x : xs) out += (out.size() > 1 ? ", " : "") + dumpValue(x);
    return out + "]";
}

} // namespace scene_json
