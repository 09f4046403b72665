// The edit log and --set (app/edit/edit_log.h, docs/edits.md): lines read with file:line errors
// naming the key, --set split and read as the row's kind, a journal written and read back, and a
// log replayed: a set then its undo is the run without the edit, bit for bit.
#include "edit_log.h"
#include "scene.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

using json = nlohmann::json;

Edit setOf(const std::string& text) {
    EditError error;
    const std::optional<Edit> edit = parseSet(text, error);
    EXPECT_TRUE(edit) << text << ": " << error.text();
    return edit ? *edit : Edit{};
}

std::string setError(const std::string& text) {
    EditError error;
    EXPECT_FALSE(parseSet(text, error)) << text;
    return error.text();
}

TEST(SetText, ReadsEachKindAsItsFlagOrFileWould) {
    Edit e = setOf("bounciness=0.5");
    EXPECT_EQ(e.kind, Edit::Kind::SetWorld);
    EXPECT_EQ(*e.value, 0.5);
    EXPECT_EQ(*setOf("gravity=0,-5").value, json({0.0, -5.0}));
    EXPECT_EQ(*setOf("gravity=[0, -5]").value, json({0, -5}));
    EXPECT_EQ(*setOf("method=turn-based").value, "turn-based");
    EXPECT_EQ(*setOf("mistakes=discrete,move-back").value, json({"discrete", "move-back"}));
    EXPECT_EQ(*setOf("mistakes=none").value, json::array());
    EXPECT_EQ(*setOf("substeps=4").value, 4.0);
    e = setOf("m2.mass=4");
    EXPECT_EQ(e.kind, Edit::Kind::SetBlock);
    EXPECT_EQ(e.block.name, "m2");
    EXPECT_EQ(e.key, "mass");
    EXPECT_EQ(*e.value, 4.0);
    EXPECT_EQ(*setOf("m2.mass=static").value, "static");
    EXPECT_EQ(*setOf("m2.size=2").value, 2.0);
    EXPECT_EQ(*setOf("m2.size=2,1").value, json({2.0, 1.0}));
    EXPECT_EQ(*setOf("m2.friction=none").value, nullptr);
    EXPECT_EQ(*setOf("m2.color=#ff0000").value, "#ff0000");
    e = setOf("blocks[1].velocity=3,0");
    EXPECT_EQ(e.block.index, 1);
    EXPECT_EQ(*e.value, json({3.0, 0.0}));
}

TEST(SetText, ANameMayHoldSpacesDotsAndEquals) {
    Edit e = setOf("m1 = 1 kg.mass=4");
    EXPECT_EQ(e.block.name, "m1 = 1 kg");
    EXPECT_EQ(*e.value, 4.0);
    e = setOf("a.b.velocity=1,2");
    EXPECT_EQ(e.block.name, "a.b");
    EXPECT_EQ(e.key, "velocity");
    e = setOf("blocks[01].mass=2"); // not a place (a leading zero): a name
    EXPECT_EQ(e.block.index, -1);
    EXPECT_EQ(e.block.name, "blocks[01]");
}

TEST(SetText, SaysWhatIsWrongWithTheKey) {
    EXPECT_EQ(setError("bounciness"), "must be KEY=VALUE, e.g. bounciness=0.5 or m2.mass=4");
    EXPECT_NE(setError("bouncyness=1").find("bouncyness: no such world key (method, dt"),
              std::string::npos);
    EXPECT_EQ(setError("m2.weight=1").rfind("m2.weight: no block field \"weight\" (name, ", 0), 0u);
}

EditLog logOf(const std::string& text) {
    const EditLogResult r = parseEditLog(text, "demo.jsonl");
    EXPECT_TRUE(r.log) << r.error.text();
    return r.log ? *r.log : EditLog{};
}

std::string logError(const std::string& text) {
    const EditLogResult r = parseEditLog(text, "demo.jsonl");
    EXPECT_FALSE(r.log) << text;
    return r.error.text();
}

TEST(EditLogText, ReadsEveryKindOfLine) {
    const EditLog log = logOf("{\"frame\": 30, \"set\": \"bounciness\", \"value\": 0.5}\n"
                              "\n"
                              "{\"frame\": 30, \"set\": \"m2.mass\", \"value\": 4}\r\n"
                              "{\"frame\": 31, \"add\": {\"position\": [1, 1], \"size\": 1}}\n"
                              "{\"frame\": 40, \"remove\": \"blocks[2]\"}\n"
                              "{\"frame\": 60, \"undo\": true}\n"
                              "{\"frame\": 61, \"redo\": true}");
    ASSERT_EQ(log.lines.size(), 6u);
    EXPECT_EQ(log.lines[0].entry.frame, 30u);
    EXPECT_EQ(log.lines[1].place, "demo.jsonl:3");
    EXPECT_EQ(log.lines[1].entry.edit.block.name, "m2");
    EXPECT_EQ(log.lines[2].entry.edit.kind, Edit::Kind::Add);
    EXPECT_EQ(log.lines[3].entry.edit.block.index, 2);
    EXPECT_EQ(log.lines[4].entry.what, JournalEntry::What::Undo);
    EXPECT_EQ(log.lines[5].entry.what, JournalEntry::What::Redo);
}

TEST(EditLogText, RefusesABadLineWithItsPlaceAndKey) {
    EXPECT_EQ(logError("{\"frame\": 1, \"set\": \"bounciness\", \"value\": 0.5}\n"
                       "{\"frame\": 2, \"set\": \"bouncyness\", \"value\": 0.5}")
                  .rfind("demo.jsonl:2: bouncyness: no such world key", 0),
              0u);
    const std::string syntax = logError("\n{\"frame\": 1, \"set\": \"bounciness\" \"value\": 0.5}");
    EXPECT_EQ(syntax.rfind("demo.jsonl:2:40: ", 0), 0u) << syntax;
    EXPECT_EQ(logError("{\"frame\": -1, \"undo\": true}"),
              "demo.jsonl:1: frame: must be a whole number from 0 to 1e7, not -1");
    EXPECT_EQ(logError("{\"frame\": 1.5, \"undo\": true}").rfind("demo.jsonl:1: frame: ", 0), 0u);
    EXPECT_EQ(logError("{\"undo\": true}"), "demo.jsonl:1: (line): missing \"frame\"");
    EXPECT_EQ(logError("{\"frame\": 1, \"set\": \"bounciness\"}"),
              "demo.jsonl:1: bounciness: missing \"value\"");
    EXPECT_EQ(logError("{\"frame\": 1, \"undo\": false}"), "demo.jsonl:1: undo: must be true");
    EXPECT_EQ(logError("{\"frame\": 1, \"undo\": true, \"redo\": true}")
                  .rfind("demo.jsonl:1: (line): must have one of", 0),
              0u);
    EXPECT_EQ(logError("{\"frame\": 1, \"undo\": true, \"when\": 3}"),
              "demo.jsonl:1: when: unknown key");
    EXPECT_EQ(logError("{\"frame\": 9, \"undo\": true}\n{\"frame\": 3, \"undo\": true}"),
              "demo.jsonl:2: frame: 3 comes after frame 9: a log lists its edits in the order "
              "they apply");
    EXPECT_EQ(logError("[1, 2]"), "demo.jsonl:1: (line): must be an object");
}

TEST(EditLogText, NeverEchoesControlBytes) {
    const std::string error =
        logError("{\"frame\": 1, \"set\": \"\\u001b]0;owned\\u0007.mass\", \"value\": 1}\n"
                 "{\"frame\": 1, \"set\": \"\\u001b[2J\", \"value\": 1}");
    EXPECT_EQ(error.find('\x1b'), std::string::npos) << error;
    EXPECT_NE(error.find("\\x1b"), std::string::npos) << error;
}

TEST(EditLogText, RefusesMoreLinesThanItHolds) {
    std::string text;
    for (std::size_t i = 0; i <= kMaxLogLines; ++i) text += "{\"frame\": 0, \"undo\": true}\n";
    EXPECT_EQ(logError(text), "demo.jsonl:100001: more than 100000 edits");
}

TEST(EditLogText, AJournalWrittenReadsBackTheSame) {
    std::vector<JournalEntry> journal;
    journal.push_back(
        {JournalEntry::What::Edit, 3, Edit::setWorld("gravity", json{0, -1.5}), false});
    journal.push_back({JournalEntry::What::Edit, 4,
                       Edit::setBlock({-1, "m1 = 1 kg"}, "velocity", json{0.1, 1.0 / 3.0}), true});
    journal.push_back({JournalEntry::What::Edit, 5, Edit::remove({2, ""}), false});
    journal.push_back({JournalEntry::What::Undo, 6, {}, false});
    const std::string text = logText(journal);
    EXPECT_EQ(text.substr(0, text.find('\n')),
              R"({"frame": 3, "set": "gravity", "value": [0,-1.5]})");
    const EditLog log = logOf(text);
    ASSERT_EQ(log.lines.size(), journal.size());
    for (std::size_t i = 0; i < journal.size(); ++i) {
        const JournalEntry& a = journal[i];
        const JournalEntry& b = log.lines[i].entry;
        EXPECT_EQ(a.what, b.what);
        EXPECT_EQ(a.frame, b.frame);
        EXPECT_EQ(a.continues, b.continues);
        EXPECT_EQ(editKey(a.edit), editKey(b.edit));
        EXPECT_EQ(*a.edit.value, *b.edit.value); // 1/3 to the bit
    }
}

// Runs `scene` for `frames` frames with the log's lines at their frames.
World replay(const Scene& scene, const std::string& logText, int frames) {
    World world = makeWorld(scene);
    std::vector<BlockLabel> labels;
    for (const BlockDef& def : scene.blocks) labels.push_back({def.name, def.color});
    LogPlayer player(logOf(logText));
    EditHistory history;
    for (int i = 0; i <= frames; ++i) {
        while (const LogLine* line = player.next(world.frame)) {
            const JournalEntry& e = line->entry;
            const EditTarget target{world, labels};
            if (e.what == JournalEntry::What::Undo)
                EXPECT_TRUE(history.undo(target, world.frame).edit);
            else if (e.what == JournalEntry::What::Redo)
                EXPECT_TRUE(history.redo(target, world.frame).edit);
            else
                EXPECT_TRUE(history.apply(target, e.edit, world.frame, e.continues).applied);
        }
        if (i < frames) world.step();
    }
    return world;
}

TEST(EditLogReplay, ASetThenItsUndoIsTheRunWithoutTheEditBitForBit) {
    const SceneResult r = loadSceneFile(SANDBOX_SCENES_DIR "/bouncing_squares.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    for (Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
        Scene scene = *r.scene;
        scene.settings.method = method;
        const World plain = replay(scene, "", 120);
        const World undone =
            replay(scene,
                   "{\"frame\": 30, \"set\": \"bounciness\", \"value\": 0.2}\n"
                   "{\"frame\": 30, \"set\": \"green.mass\", \"value\": 40}\n"
                   "{\"frame\": 30, \"undo\": true}\n{\"frame\": 30, \"undo\": true}",
                   120);
        EXPECT_EQ(stateHash(undone), stateHash(plain)) << methodName(method);
        // The edit, not undone, changes the run (the test can fail).
        const World edited =
            replay(scene, "{\"frame\": 30, \"set\": \"bounciness\", \"value\": 0.2}", 120);
        EXPECT_NE(stateHash(edited), stateHash(plain)) << methodName(method);
        // Undone and done again: the same as done once.
        const World redone = replay(scene,
                                    "{\"frame\": 30, \"set\": \"bounciness\", \"value\": 0.2}\n"
                                    "{\"frame\": 30, \"undo\": true}\n"
                                    "{\"frame\": 30, \"redo\": true}",
                                    120);
        EXPECT_EQ(stateHash(redone), stateHash(edited)) << methodName(method);
    }
}

} // namespace
