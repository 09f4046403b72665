// jsonRootHasKey (scene_json.h): the cheap test of "does this JSON text's root object have this
// key" that tells a lesson from a scene. It must give the answer a full parse gives for every
// input (the text parses with every check of parseJsonText, its root is an object, and it has
// the key), including text that is not JSON at all.
#include "scene_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
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
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(SANDBOX_SCENES_DIR)) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json") continue;
        std::string text;
        ASSERT_FALSE(readJsonFile(path, text)) << path;
        EXPECT_FALSE(jsonRootHasKey(text, "steps")) << path;
        EXPECT_TRUE(jsonRootHasKey(text, "blocks")) << path;
        EXPECT_EQ(jsonRootHasKey(text, "world"), fullParseAnswer(text, "world")) << path;
        ++scenes;
    }
    EXPECT_GT(scenes, 10);
}
