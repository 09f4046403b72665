// Numbers kept as set, keys kept through save, link and open (issue 41): every shipped scene and
// every key of the settings table (world keys and block fields) survives the window's save and the
// browser's link, opened again, to the byte; a value the panel shows as 0.44 is saved as 0.44.
#include "app.h"
#include "app_setup.h"
#include "classroom.h"
#include "settings_table.h"
#include "test_fixtures.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

fs::path workDir(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("round_trip_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

App appOn(const std::string& path) {
    App app;
    std::string error;
    EXPECT_TRUE(setupApp(app, Options{}, "", &error)) << error;
    EXPECT_TRUE(loadScene(app, path)) << path << ": " << app.ui.messages.error;
    return app;
}

// The file the window's Save writes for what `app` shows.
std::string saved(App& app, const fs::path& path) {
    EXPECT_TRUE(saveCurrentScene(app, path.string())) << app.ui.messages.error;
    return readText(path);
}

// The scene a link carries (main_web.cpp puts this text, compressed, in #scene=), as the page
// writes it into the browser's file system when the link is opened.
fs::path linked(const App& app, const fs::path& path) {
    writeText(path, sceneToJson(app.sim.currentScene()));
    return path;
}

// Every key of `original` is in `saved` with the same value (numbers as doubles: 3 and 3.0 are
// one number); `saved` may hold more (the defaults it writes). `where` names the JSON path.
void expectHolds(const json& original, const json& saved, const std::string& where) {
    if (original.is_object()) {
        ASSERT_TRUE(saved.is_object()) << where;
        for (const auto& [key, value] : original.items()) {
            ASSERT_TRUE(saved.contains(key)) << where << "." << key << " was lost";
            expectHolds(value, saved[key], where + "." + key);
        }
    } else if (original.is_array()) {
        ASSERT_TRUE(saved.is_array() && saved.size() == original.size()) << where;
        for (std::size_t i = 0; i < original.size(); ++i)
            expectHolds(original[i], saved[i], where + "[" + std::to_string(i) + "]");
    } else if (original.is_number()) {
        ASSERT_TRUE(saved.is_number()) << where;
        EXPECT_EQ(original.get<double>(), saved.get<double>()) << where;
    } else {
        EXPECT_EQ(original, saved) << where;
    }
}

// Save, then open the saved file and save again; link, then open the link and save: the three
// files are one. Returns the first.
std::string expectRoundTrips(App& app, const fs::path& dir) {
    const std::string first = saved(app, dir / "saved.json");
    App linkedApp = appOn(linked(app, dir / "link.json").string());
    EXPECT_EQ(saved(linkedApp, dir / "link_saved.json"), first) << "link and open";
    App again = appOn((dir / "saved.json").string());
    EXPECT_EQ(saved(again, dir / "saved_again.json"), first) << "save and open";
    return first;
}

std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(SANDBOX_SCENES_DIR))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

TEST(RoundTrip, EveryShippedSceneKeepsEveryKeyThroughSaveLinkAndOpen) {
    const std::vector<fs::path> scenes = shippedScenes();
    ASSERT_GE(scenes.size(), 30u);
    for (const fs::path& scene : scenes) {
        SCOPED_TRACE(scene.filename().string());
        App app = appOn(scene.string());
        const std::string file = expectRoundTrips(app, workDir(scene.stem().string()));
        json original = json::parse(readText(scene));
        for (json& block : original["blocks"]) // a square's size is written as [w, h]
            if (block["size"].is_number())
                block["size"] = json::array({block["size"], block["size"]});
        expectHolds(original, json::parse(file), "");
    }
}

// A value for `row` that is not its default and is within its limits: the panel's kind of
// number (0.44, as a slider shows it), the pair (0.44, -3.7), the next whole number, the choice
// `choice`, every name of a set.
void setOther(const settings_table::WorldKey& row, WorldSettings& s, int choice) {
    using settings_table::Kind;
    switch (row.kind) {
    case Kind::Number:
        s.*row.number = row.shown.asRate ? 1.0 / 61.0 : 0.44;
        break;
    case Kind::Whole:
        s.*row.whole += 3;
        break;
    case Kind::Pair:
        s.*row.pair = Vec2{0.44, -3.7};
        break;
    case Kind::Choice:
        row.setChoice(s, choice);
        break;
    case Kind::NameSet:
        s.*row.bits = static_cast<std::uint8_t>((1u << row.names.count) - 1u);
        break;
    case Kind::Flag:
        s.*row.flag = !(s.*row.flag);
        break;
    }
}

TEST(RoundTrip, EveryWorldKeyOfTheTableSurvivesSaveLinkAndOpen) {
    const std::string scene = std::string(SANDBOX_SCENES_DIR) + "/lecture_example_1.json";
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (!row.inScene) continue;
        const int choices = row.kind == settings_table::Kind::Choice ? row.names.count : 1;
        for (int choice = 0; choice < choices; ++choice) {
            SCOPED_TRACE(std::string(row.key) + " " + std::to_string(choice));
            App app = appOn(scene);
            WorldSettings& s = app.sim.world().settings;
            setOther(row, s, choice);
            const WorldSettings set = s;
            const fs::path dir = workDir(std::string(row.key) + std::to_string(choice));
            expectRoundTrips(app, dir);
            App opened = appOn((dir / "saved.json").string());
            EXPECT_TRUE(settings_table::same(row, opened.sim.world().settings, set));
            EXPECT_TRUE(opened.sim.scene.duration && *opened.sim.scene.duration == 3.0);
        }
    }
}

TEST(RoundTrip, EveryBlockFieldSurvivesSaveLinkAndOpen) {
    // lecture_example_1's m2 given every field the table has: its own friction, a force, a
    // colour, then each kind.
    const std::string scene = std::string(SANDBOX_SCENES_DIR) + "/lecture_example_1.json";
    for (const BodyKind kind : {BodyKind::Dynamic, BodyKind::Static, BodyKind::Kinematic}) {
        SCOPED_TRACE(static_cast<int>(kind));
        App app = appOn(scene);
        Block& b = app.sim.world().blocks[1];
        b.friction = 0.44;
        if (kind == BodyKind::Dynamic) {
            b.force = Vec2{0.44, -3.7};
            b.mass = 0.44;
        } else {
            app.sim.setBlockKind(1, kind);
            b.velocity = kind == BodyKind::Kinematic ? Vec2{0.44, 0.0} : Vec2{};
        }
        app.sim.labels[1].color = "#4080d0";
        app.sim.noteEdit(true);
        const fs::path dir = workDir("block" + std::to_string(static_cast<int>(kind)));
        const json file = json::parse(expectRoundTrips(app, dir));
        const json& m2 = file["blocks"][1];
        for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
            const bool written = row.kind != settings_table::BlockKind::Force ||
                                 kind == BodyKind::Dynamic; // a force only on a dynamic block
            EXPECT_EQ(m2.contains(row.key), written) << row.key << " in " << m2.dump();
        }
        EXPECT_EQ(m2["friction"], 0.44);
        if (kind == BodyKind::Dynamic) {
            EXPECT_EQ(m2["mass"], 0.44);
        }
    }
}

// The panel's slider and drag fields hold floats; what is saved is what they show.
TEST(RoundTrip, APanelsValueIsKeptAsShown) {
    const float slid = 0.44f; // a slider at 0.44 holds 0.4399999976158142
    EXPECT_NE(static_cast<double>(slid), 0.44);
    EXPECT_EQ(shownNumber(slid, "%.2f"), 0.44);
    EXPECT_EQ(shownNumber(-9.8100004196167f, "%.2f"), -9.81);
    EXPECT_EQ(shownNumber(0.0012345f, "%.3g kg/m³"), 0.00123);
    EXPECT_EQ(shownNumber(61.0004f, "%.0f Hz"), 61.0);
    EXPECT_EQ(shownNumber(2.5f, "%.2fx"), 2.5);
    EXPECT_EQ(shownNumber(1234.5f, "%.3g kg"), 1230.0);
    EXPECT_EQ(shownNumber(7.0, "%d"), 7.0); // not a floating-point format: as it is
    EXPECT_EQ(shownNumber(0.4399999976158142, "100%% %.2f"), 0.44);
    // The panel's own formats, from the table, give the numbers as they read.
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (row.kind != settings_table::Kind::Number || !row.inScene) continue;
        SCOPED_TRACE(row.key);
        const double value = row.shown.asRate ? 61.0 : 0.44;
        const double kept = shownNumber(static_cast<float>(value), row.panel.format);
        EXPECT_EQ(kept, value);
    }
    // And saved so: the file says 0.44.
    App app = appOn(std::string(SANDBOX_SCENES_DIR) + "/lecture_example_1.json");
    app.sim.world().settings.bounciness = shownNumber(slid, "%.2f");
    const std::string file = saved(app, workDir("shown") / "saved.json");
    EXPECT_NE(file.find("\"bounciness\": 0.44,"), std::string::npos) << file;
    EXPECT_NE(file.find("\"duration\": 3.0,"), std::string::npos) << file;
}

} // namespace
