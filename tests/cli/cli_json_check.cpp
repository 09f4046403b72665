// Runs `sandbox-cli run SCENE --json` on the shipped scenes and checks the output: one JSON
// object with every key of the contract, the blocks in file order, and the lecture's numbers.
// Usage: cli_json_check SANDBOX_CLI SCENES_DIR. Exit 0 when every check passes.
#include "scene.h"

#include "cli_check.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace {

using cli_check::capture;
using cli_check::check;

bool isVec2(const nlohmann::json& j) {
    return j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number();
}

// Runs the scene and checks the shape of the output; returns the parsed object (or null).
nlohmann::json runJson(const std::string& cli, const std::string& scenePath,
                       const std::string& options) {
    const std::string label = scenePath + " " + options;
    int status = -1;
    const std::string out =
        capture("'" + cli + "' run '" + scenePath + "' --json " + options, status);
    check(status == 0, label + ": exit status 0");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(out);
    } catch (const std::exception& e) {
        check(false, label + ": output is JSON (" + e.what() + "): " + out.substr(0, 200));
        return nullptr;
    }
    check(j.is_object(), label + ": one JSON object");
    if (!j.is_object()) return nullptr;
    for (const char* key :
         {"sim_time", "steps", "collisions", "max_penetration", "kinetic_energy",
          "potential_energy", "event_cap_hits", "wall_ms", "dt", "substeps", "bounciness"})
        check(j.contains(key) && j[key].is_number(), label + ": number " + key);
    for (const char* key : {"scene", "method"})
        check(j.contains(key) && j[key].is_string(), label + ": string " + key);
    check(j.contains("momentum") && isVec2(j["momentum"]), label + ": momentum [px, py]");
    check(j.contains("blocks") && j["blocks"].is_array(), label + ": blocks array");
    if (!j.contains("blocks") || !j["blocks"].is_array()) return nullptr;

    const SceneResult scene = loadSceneFile(scenePath);
    check(scene.scene.has_value(), label + ": scene loads");
    if (!scene.scene) return nullptr;
    const auto& blocks = j["blocks"];
    check(blocks.size() == scene.scene->blocks.size(), label + ": one entry per block");
    for (std::size_t i = 0; i < blocks.size() && i < scene.scene->blocks.size(); ++i) {
        const auto& b = blocks[i];
        const std::string at = label + ": blocks[" + std::to_string(i) + "]";
        check(b.contains("name") && b["name"] == scene.scene->blocks[i].name, at + " name");
        check(b.contains("position") && isVec2(b["position"]), at + " position");
        check(b.contains("velocity") && isVec2(b["velocity"]), at + " velocity");
    }
    return j;
}

bool near(const nlohmann::json& value, double expected) {
    return value.is_number() && std::abs(value.get<double>() - expected) <= 1e-9;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: cli_json_check SANDBOX_CLI SCENES_DIR\n";
        return 2;
    }
    const std::string cli = argv[1];
    const std::string dir = std::string(argv[2]) + "/";

    for (const char* scene :
         {"lecture_example_1", "lecture_example_2", "bouncing_squares", "newtons_cradle",
          "resting_stack", "bullet_wall", "moving_platform", "gas_500"}) {
        const nlohmann::json j = runJson(cli, dir + scene + ".json", "--steps 30");
        if (j.is_object()) check(j["steps"] == 30, std::string(scene) + ": steps 30");
    }

    // The lecture's examples, with each method: one collision in the first second.
    for (const char* method : {"perfect", "move-and-correct", "turn-based"}) {
        const std::string m = std::string("--method ") + method;
        const nlohmann::json a = runJson(cli, dir + "lecture_example_1.json", "--time 1 " + m);
        if (a.is_object()) {
            check(a["steps"] == 60, m + ": --time 1 at dt 1/60 is 60 steps");
            check(a["method"] == method, m + ": method reported");
            check(near(a["blocks"][0]["velocity"][0], -2.0), m + ": example 1, v1' = -2");
            check(near(a["blocks"][1]["velocity"][0], 4.0), m + ": example 1, v2' = 4");
            check(near(a["momentum"][0], 6.0), m + ": example 1, momentum 6");
            check(a["collisions"] == 1, m + ": example 1, one collision");
        }
        const nlohmann::json b = runJson(cli, dir + "lecture_example_2.json", "--time 1 " + m);
        if (b.is_object()) {
            check(near(b["blocks"][0]["velocity"][0], 0.0), m + ": example 2, v1' = 0");
            check(near(b["blocks"][1]["velocity"][0], 0.0), m + ": example 2, v2' = 0");
        }
    }

    // Overrides show up in the output.
    const nlohmann::json o = runJson(cli, dir + "bouncing_squares.json",
                                     "--steps 5 --dt 0.01 --substeps 4 --bounciness 0.5 "
                                     "--gravity 0,-1");
    if (o.is_object()) {
        check(o["dt"] == 0.01 && o["substeps"] == 4 && o["bounciness"] == 0.5, "overrides");
        check(near(o["sim_time"], 0.05), "5 steps of 0.01 s");
    }

    if (cli_check::failures == 0) std::cout << "all checks passed\n";
    return cli_check::failures == 0 ? 0 : 1;
}
