// sandbox-cli run --set and --edits (docs/edits.md): `run SCENE --set bounciness=0.5 --json` is
// the run of the scene saved with C = 0.5; a log that sets and then undoes is the run without
// it, bit for bit (every number of --json but the wall time), in the three methods.
// Usage: cli_edits_check SANDBOX_CLI SCENES_DIR WORK_DIR. Exit 0 when every check passes.
#include "scene.h"

#include "cli_check.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <string>

namespace {

using cli_check::capture;
using cli_check::check;

// `run ARGS --json`, wall time left out; null when it fails.
nlohmann::json runJson(const std::string& cli, const std::string& args) {
    int status = -1;
    const std::string out = capture("'" + cli + "' run " + args + " --json", status);
    check(status == 0, args + ": exit status 0");
    nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
    check(j.is_object(), args + ": one JSON object");
    if (!j.is_object()) return nullptr;
    j.erase("wall_ms");
    return j;
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: cli_edits_check SANDBOX_CLI SCENES_DIR WORK_DIR\n";
        return 2;
    }
    const std::string cli = argv[1], scenes = argv[2], work = argv[3];
    for (const char* name : {"bouncing_squares", "lecture_example_1", "newtons_cradle"}) {
        const std::string path = scenes + "/" + name + ".json";
        const SceneResult loaded = loadSceneFile(path);
        check(loaded.scene.has_value(), path + " loads");
        if (!loaded.scene) continue;
        // The scene saved with C = 0.5 (and its second block 4 kg, by its name).
        Scene saved = *loaded.scene;
        saved.settings.bounciness = 0.5;
        const std::string block = saved.blocks[1].name;
        saved.blocks[1].mass = 4.0;
        const std::string savedPath = work + "/" + name + "_saved.json";
        check(saveSceneFile(saved, savedPath, nullptr), savedPath + " written");
        const std::string set = "--set bounciness=0.5 --set '" + block + ".mass=4'";
        const nlohmann::json byFlag = runJson(cli, "'" + path + "' " + set);
        const nlohmann::json bySave = runJson(cli, "'" + savedPath + "'");
        check(!byFlag.is_null() && byFlag == bySave,
              std::string(name) + ": --set equals the scene saved so");
        check(runJson(cli, "'" + path + "' --set blocks[1].mass=4 --set bounciness=0.5") == bySave,
              std::string(name) + ": the block by its place too");

        // A set and its undo: the run without them; the set alone: another run.
        const std::string undone = work + "/" + name + "_undone.jsonl";
        write(undone, "{\"frame\": 20, \"set\": \"bounciness\", \"value\": 0.3}\n"
                      "{\"frame\": 20, \"set\": \"blocks[0].velocity\", \"value\": [1, 2]}\n"
                      "{\"frame\": 20, \"undo\": true}\n"
                      "{\"frame\": 20, \"undo\": true}\n");
        const std::string kept = work + "/" + name + "_kept.jsonl";
        write(kept, "{\"frame\": 20, \"set\": \"blocks[0].velocity\", \"value\": [1, 2]}\n");
        for (const char* method : {"perfect", "move-and-correct", "turn-based"}) {
            const std::string base = "'" + path + "' --steps 120 --method " + method;
            const nlohmann::json plain = runJson(cli, base);
            check(!plain.is_null() && runJson(cli, base + " --edits '" + undone + "'") == plain,
                  std::string(name) + " " + method + ": a set and its undo change nothing");
            check(runJson(cli, base + " --edits '" + kept + "'") != plain,
                  std::string(name) + " " + method + ": the set alone changes the run");
        }
    }
    if (cli_check::failures == 0) std::cout << "ok\n";
    return cli_check::failures == 0 ? 0 : 1;
}
