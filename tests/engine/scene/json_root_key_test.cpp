// jsonRootHasKey (scene_json.h): the cheap test of "does this JSON text's root object have this
// key" that tells a lesson from a scene. It must give the answer a full parse gives for every
// input (the text parses with every check of parseJsonText, its root is an object, and it has
// the key), including text that is not JSON at all.
#include "scene.h"
#include "scene_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

// The answer by a full parse: what isLessonText computed before (a JSON DOM of the whole text).
bool fullParseAnswer(const std::string& text, const std::string& key) {
    nlohmann::json root;
    if (parseJsonText(text, "", root)) return false;
    return root.is_object() && root.contains(key);
}

std::string deep(char open, int levels) {
    return std::string(static_cast<std::size_t>(levels), open);
}

// Every shipped scene file: its path and its text.
struct ShippedScene {
    std::string path, text;
};
std::vector<ShippedScene> shippedScenes() {
    std::vector<ShippedScene> out;
    for (const auto& entry : std::filesystem::directory_iterator(SANDBOX_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        ShippedScene scene{entry.path().string(), ""};
        EXPECT_FALSE(readJsonFile(scene.path, scene.text)) << scene.path;
        out.push_back(std::move(scene));
    }
    return out;
}

} // namespace

TEST(JsonRootHasKey, AnswersAsAFullParseForEveryKindOfInput) {
    const std::vector<std::pair<std::string, bool>> cases = {
        {R"({"name": "l", "steps": []})", true},                                  // a lesson
        {R"({"name": "s", "blocks": [{"position": [1, 2], "size": 1}]})", false}, // a scene
        {R"({"name": "s", "world": {"steps": 3}, "blocks": []})", false},         // nested "steps"
        {R"({"blocks": [{"steps": 1}], "name": "s"})", false},                    // inside an array
        {R"([{"steps": []}])", false},                                            // an array root
        {R"("steps")", false},                                                    // a string root
        {"3", false},
        {"null", false},
        {R"({"st\u0065ps": []})", true},                    // the key is compared after its escapes
        {R"({"steps": [], "steps": []})", false},           // a duplicate key: refused
        {R"({"a": 1, "a": 2, "steps": []})", false},        // a duplicate before the key
        {R"({"steps": [], "a": {"b": 1, "b": 2}})", false}, // a duplicate after it
        {R"({"steps": [)", false},                          // cut short after the key
        {R"({"steps": [] )", false},                        // the root never closed
        {R"({"steps": []} junk)", false},                   // junk after the root
        {R"({"junk" "steps": []})", false},                 // bad syntax before the key
        {R"({"x": 1e400, "steps": []})", false},            // a number out of range
        {R"({"steps": [1e400]})", false},
        {std::string("{\"steps\": []}\0junk", 17), false}, // a NUL byte after the root
        {std::string("{\"steps\": [\0]}", 14), false},     // and inside
        {std::string("{\"s\0teps\": []}", 14), false},
        {"", false}, // an empty file
        {"   \n\t ", false},
        {"{", false},
        {"{}", false},
        {"{\"steps\": " + deep('[', 70) + std::string(70, ']') + "}", false}, // too deep
        {"{\"steps\": " + deep('[', 60) + std::string(60, ']') + "}", true},  // deep enough
        {deep('{', 100000), false},
        {deep('[', 100000), false},
        {"\xEF\xBB\xBF{\"steps\": []}", true}, // a byte-order mark, which nlohmann skips
        {"{\"steps\": \"\xff\"}", false},      // invalid UTF-8 in a string
    };
    for (const auto& [text, expected] : cases) {
        EXPECT_EQ(fullParseAnswer(text, "steps"), expected) << text.substr(0, 80);
        EXPECT_EQ(jsonRootHasKey(text, "steps"), expected) << text.substr(0, 80);
    }
}

TEST(JsonRootHasKey, AnswersAsAFullParseForEveryShippedScene) {
    const std::vector<ShippedScene> scenes = shippedScenes();
    EXPECT_GT(scenes.size(), 10u);
    for (const auto& [path, text] : scenes) {
        EXPECT_FALSE(jsonRootHasKey(text, "steps")) << path;
        EXPECT_TRUE(jsonRootHasKey(text, "blocks")) << path;
        EXPECT_EQ(jsonRootHasKey(text, "world"), fullParseAnswer(text, "world")) << path;
    }
}

// sceneNameOf (scene_json.h): the name the scene library lists a file by, read in the same one
// pass. Every key the loader accepts at the top level (kSceneKeys) keeps the file a scene; any
// other key, a "name" that is not a string or missing, or text that is not JSON makes it none.
TEST(SceneNameOf, ReadsTheNameOfAFileWhoseTopLevelIsAScenes) {
    const std::vector<std::pair<std::string, std::optional<std::string>>> cases = {
        {R"({"name": "Pile", "blocks": []})", "Pile"},
        {R"({"blocks": [{"name": 1}], "name": "n"})", "n"}, // a nested "name" is a block's
        {R"({"name": "", "blocks": []})", ""},              // empty: listed by its file name
        {R"({"n\u0061me": "escaped"})", "escaped"},
        {R"({"name": "l", "steps": []})", std::nullopt}, // a lesson
        {R"({"blocks": []})", std::nullopt},             // no name
        {R"({"name": 3})", std::nullopt},
        {R"({"name": {"a": "b"}})", std::nullopt},
        {R"({"name": ["x"]})", std::nullopt},
        {R"({"name": null})", std::nullopt},
        {R"([{"name": "x"}])", std::nullopt},
        {R"("name")", std::nullopt},
        {R"({"name": "x")", std::nullopt},       // cut short
        {R"({"name": "x"} junk)", std::nullopt}, // junk after the root
        {R"({"name": "x", "blocks": [)", std::nullopt},
        {"", std::nullopt},
        {deep('{', 100000), std::nullopt},
    };
    for (const auto& [text, expected] : cases)
        EXPECT_EQ(sceneNameOf(text), expected) << text.substr(0, 80);
    // The loader's top-level keys, each in a file: a scene's name whatever the key's value.
    for (const char* key : kSceneKeys) {
        if (std::string(key) == "name") continue;
        const std::string text = std::string(R"({"name": "k", ")") + key + R"(": 0})";
        EXPECT_EQ(sceneNameOf(text), std::optional<std::string>("k")) << key;
    }
}

TEST(SceneNameOf, GivesEveryShippedScenesNameAsTheLoaderReadsIt) {
    const std::vector<ShippedScene> scenes = shippedScenes();
    EXPECT_GT(scenes.size(), 10u);
    for (const auto& [path, text] : scenes) {
        const SceneResult loaded = parseScene(text, path);
        ASSERT_TRUE(loaded.scene) << path;
        EXPECT_EQ(sceneNameOf(text), std::optional<std::string>(loaded.scene->name)) << path;
    }
}
