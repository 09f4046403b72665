// The one table of the world's settings and the block's fields (settings_table.h), row by row:
// every scene key is read at its JSON path, written and read back to the same value, compared,
// given a flag that takes what the file takes, and shown with its unit. A row added to the table
// is covered here without a new test.
#include "scene.h"
#include "scene_json.h"
#include "settings_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using settings_table::Kind;
using settings_table::WorldKey;

// A valid value of `row` other than the default (the far end of its range, another name, every
// name of a set, the other truth value).
WorldSettings otherValue(const WorldKey& row) {
    WorldSettings s = defaultWorldSettings();
    const WorldSettings d = s;
    switch (row.kind) {
    case Kind::Number:
        s.*row.number = d.*row.number == row.range.max ? row.range.min : row.range.max;
        break;
    case Kind::Whole:
        s.*row.whole =
            static_cast<int>(d.*row.whole == row.range.max ? row.range.min : row.range.max);
        break;
    case Kind::Pair:
        s.*row.pair = Vec2{row.range.max, row.range.min};
        break;
    case Kind::Choice:
        row.setChoice(s, (row.getChoice(d) + 1) % row.names.count);
        break;
    case Kind::NameSet:
        s.*row.bits = static_cast<std::uint8_t>((1u << row.names.count) - 1);
        break;
    case Kind::Flag:
        s.*row.flag = !(d.*row.flag);
        break;
    }
    return s;
}

std::string sceneWithWorld(const std::string& world) {
    return R"({"name": "t", "world": {)" + world + R"(}, "blocks": []})";
}

std::vector<const WorldKey*> sceneRows() {
    std::vector<const WorldKey*> rows;
    for (const WorldKey& row : settings_table::worldKeys())
        if (row.inScene) rows.push_back(&row);
    return rows;
}

TEST(SettingsTable, KeysAreUniqueAndEveryShownRowHasItsWords) {
    std::set<std::string> keys;
    for (const WorldKey& row : settings_table::worldKeys()) {
        EXPECT_TRUE(keys.insert(row.key).second) << row.key;
        if (!row.inScene) continue;
        EXPECT_NE(std::string(row.shown.name), "") << row.key;
        EXPECT_EQ(settings_table::findWorldKey(row.key), &row);
    }
    EXPECT_EQ(settings_table::findWorldKey("rest_speed"), nullptr); // engine-only: no scene key
}

// Each row's other value survives a file: read, written, read again; equality sees the change.
TEST(SettingsTable, EveryRowRoundTripsThroughAFile) {
    for (const WorldKey* row : sceneRows()) {
        Scene scene;
        scene.name = "t";
        scene.settings = otherValue(*row);
        EXPECT_FALSE(settings_table::same(*row, scene.settings, defaultWorldSettings()))
            << row->key;
        const std::string text = sceneToJson(scene);
        EXPECT_NE(text.find("\"" + std::string(row->key) + "\": "), std::string::npos) << text;
        const SceneResult back = parseScene(text, "t.json");
        ASSERT_TRUE(back.scene) << row->key << ": " << back.error.text();
        EXPECT_TRUE(settings_table::sameSceneSettings(back.scene->settings, scene.settings))
            << row->key;
        EXPECT_TRUE(*back.scene == scene) << row->key;
        Scene defaults = scene;
        defaults.settings = defaultWorldSettings();
        EXPECT_FALSE(defaults == scene) << row->key;
    }
}

// The value alone, as a scene file's "world" holds it, is read into the row's member.
TEST(SettingsTable, EveryRowIsReadFromItsKey) {
    for (const WorldKey* row : sceneRows()) {
        const WorldSettings other = otherValue(*row);
        const std::string value = scene_json::dumpValue(settingJson(*row, other));
        const SceneResult r =
            parseScene(sceneWithWorld("\"" + std::string(row->key) + "\": " + value), "t.json");
        ASSERT_TRUE(r.scene) << row->key << ": " << r.error.text();
        EXPECT_TRUE(settings_table::same(*row, r.scene->settings, other)) << row->key;
        WorldSettings copied = defaultWorldSettings();
        settings_table::copy(*row, other, copied);
        EXPECT_TRUE(settings_table::sameSceneSettings(copied, other)) << row->key;
    }
}

// A value of the wrong type, and one beyond the range, are refused at "world.KEY" (or inside it).
TEST(SettingsTable, EveryRowRefusesBadValuesAtItsPath) {
    for (const WorldKey* row : sceneRows()) {
        const std::string path = "t.json: world." + std::string(row->key);
        const std::string key = "\"" + std::string(row->key) + "\": ";
        const std::string wrongType =
            row->kind == Kind::Number || row->kind == Kind::Whole ? "\"1\"" : "{}";
        const SceneResult bad = parseScene(sceneWithWorld(key + wrongType), "t.json");
        ASSERT_FALSE(bad.scene) << row->key;
        EXPECT_EQ(bad.error.where, path);
        std::string beyond;
        switch (row->kind) {
        case Kind::Number:
        case Kind::Whole:
            beyond = limits::formatNumber(row->range.max * 2 + 1);
            break;
        case Kind::Pair:
            beyond = "[0, " + limits::formatNumber(row->range.max * 2 + 1) + "]";
            break;
        case Kind::Choice:
            beyond = "\"no such name\"";
            break;
        case Kind::NameSet:
            beyond = "[\"no such name\"]";
            break;
        case Kind::Flag:
            beyond = "2";
            break;
        }
        const SceneResult out = parseScene(sceneWithWorld(key + beyond), "t.json");
        ASSERT_FALSE(out.scene) << row->key;
        EXPECT_EQ(out.error.where.rfind(path, 0), 0u) << out.error.text();
        EXPECT_NE(out.error.message.find("must be"), std::string::npos) << out.error.text();
    }
}

// A flag takes the text of the value a file takes, and refuses what the file refuses.
TEST(SettingsTable, EveryFlagTakesWhatTheFileTakes) {
    for (const WorldKey* row : sceneRows()) {
        if (!*row->cli.flag) continue;
        const WorldSettings other = otherValue(*row);
        std::string text;
        switch (row->kind) {
        case Kind::Number:
            text = limits::formatNumber(other.*row->number);
            break;
        case Kind::Whole:
            text = std::to_string(other.*row->whole);
            break;
        case Kind::Pair:
            text = limits::formatNumber((other.*row->pair).x) + "," +
                   limits::formatNumber((other.*row->pair).y);
            break;
        case Kind::Choice:
            text = row->names.name(row->getChoice(other));
            break;
        case Kind::NameSet:
            text = row->names.name(row->names.count - 1);
            break;
        case Kind::Flag:
            text = other.*row->flag ? "on" : "off";
            break;
        }
        WorldSettings s = defaultWorldSettings();
        const settings_table::FlagProblem ok = settings_table::readFlag(*row, text, s);
        EXPECT_EQ(ok.expected, "") << row->cli.flag << " " << text;
        EXPECT_FALSE(settings_table::same(*row, s, defaultWorldSettings())) << row->cli.flag;
        WorldSettings untouched = defaultWorldSettings();
        const settings_table::FlagProblem bad =
            settings_table::readFlag(*row, "no such value", untouched);
        EXPECT_EQ(bad.expected.rfind("must be ", 0), 0u) << row->cli.flag << ": " << bad.expected;
        EXPECT_TRUE(settings_table::sameAllSettings(untouched, defaultWorldSettings()));
        EXPECT_NE(settings_table::flagHelp(*row), "");
    }
}

// The messages the table builds are those sandbox-cli printed before it (tests/cli pins more).
TEST(SettingsTable, FlagMessagesAndHelp) {
    WorldSettings s = defaultWorldSettings();
    const WorldKey& method = *settings_table::findWorldKey("method");
    EXPECT_EQ(settings_table::readFlag(method, "x", s).expected,
              "must be perfect, move-and-correct or turn-based");
    const WorldKey& gravity = *settings_table::findWorldKey("gravity");
    EXPECT_EQ(settings_table::readFlag(gravity, "1", s).expected,
              "must be GX,GY in m/s^2, e.g. 0,-9.81");
    const settings_table::FlagProblem half = settings_table::readFlag(gravity, "0,1e10", s);
    EXPECT_EQ(half.text, "1e10"); // the component refused, as before
    EXPECT_EQ(half.expected, "must be from -1e9 to 1e9 m/s^2, not 1e10");
    const WorldKey& mistakes = *settings_table::findWorldKey("mistakes");
    EXPECT_EQ(settings_table::readFlag(mistakes, "q", s).expected,
              "must be discrete, move-back, first-found, no-approach-test or none");
    EXPECT_EQ(settings_table::readFlag(mistakes, "discrete", s).expected, "");
    EXPECT_TRUE(s.has(Mistake::Discrete));
    EXPECT_EQ(settings_table::readFlag(mistakes, "none", s).expected, "");
    EXPECT_EQ(s.mistakes, 0);
    EXPECT_EQ(settings_table::flagHelp(*settings_table::findWorldKey("dt")),
              "Seconds per frame, from 1e-6 to 1 s (default: the scene's)");
    EXPECT_EQ(settings_table::flagHelp(gravity),
              "Gravity GX,GY, e.g. 0,-9.81, each from -1e9 to 1e9 m/s^2 (default: the scene's)");
}

TEST(SettingsTable, ShownValuesCarryTheirUnits) {
    WorldSettings s = defaultWorldSettings();
    s.dt = 1.0 / 30.0;
    s.drag = 1.5;
    s.set(Mistake::Discrete, true);
    s.set(Mistake::MoveBack, true);
    auto shown = [&](const char* key) {
        return settings_table::shownValue(*settings_table::findWorldKey(key), s,
                                          [](double v) { return limits::formatNumber(v); });
    };
    EXPECT_EQ(shown("gravity"), "(0, -9.81) m/s²");
    EXPECT_EQ(shown("dt"), "30 Hz");
    EXPECT_EQ(shown("drag"), "1.5 kg/m³");
    EXPECT_EQ(shown("method"), "perfect");
    EXPECT_EQ(shown("mistakes"), "discrete and move-back");
    EXPECT_EQ(settings_table::logValue(*settings_table::findWorldKey("mistakes"), s),
              "discrete,move-back");
    EXPECT_EQ(settings_table::logValue(*settings_table::findWorldKey("gravity"), s), "0,-9.81");
}

// The engine-only rows count for the timeline's comparison, not for a scene's.
TEST(SettingsTable, EngineOnlyRowsCountOnlyForAllSettings) {
    for (const WorldKey& row : settings_table::worldKeys()) {
        const WorldSettings other = otherValue(row);
        EXPECT_FALSE(settings_table::sameAllSettings(other, defaultWorldSettings())) << row.key;
        EXPECT_EQ(settings_table::sameSceneSettings(other, defaultWorldSettings()), !row.inScene)
            << row.key;
    }
    WorldSettings nan = defaultWorldSettings();
    nan.drag = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(settings_table::sameAllSettings(nan, nan)); // the timeline's "same bits"
}

// Every block key of the table is read, written and compared; required ones are required.
TEST(SettingsTable, BlockKeys) {
    BlockDef a;
    a.name = "n";
    a.position = {2, 3};
    a.size = {1, 2};
    a.velocity = {4, 5};
    a.mass = 6;
    a.force = {7, 8};
    a.color = "#102030";
    Scene scene;
    scene.name = "t";
    scene.blocks = {a};
    const std::string text = sceneToJson(scene);
    for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
        EXPECT_NE(text.find("\"" + std::string(row.key) + "\": "), std::string::npos) << row.key;
        EXPECT_EQ(&settings_table::blockKey(row.key), &row);
    }
    const SceneResult back = parseScene(text, "t.json");
    ASSERT_TRUE(back.scene) << back.error.text();
    EXPECT_TRUE(back.scene->blocks[0] == a);
    BlockDef other = a;
    other.kind = BodyKind::Static;
    other.force = {};
    EXPECT_FALSE(other == a);
    BlockDef otherStatic = other;
    otherStatic.mass = 99; // not in the file for a static block
    EXPECT_TRUE(otherStatic == other);
    for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
        if (!row.required) continue;
        const SceneResult missing =
            parseScene(R"({"name": "t", "blocks": [{)" +
                           std::string(row.key == std::string("size") ? R"("position": [2, 2])"
                                                                      : R"("size": 1)") +
                           "}]}",
                       "t.json");
        ASSERT_FALSE(missing.scene);
        EXPECT_EQ(missing.error.text(),
                  "t.json: blocks[0]: missing \"" + std::string(row.key) + "\"");
    }
}

} // namespace
