// The one door (app/edit): edits applied with the settings table's limits, refused with the key,
// undone and done again exactly (bit for bit: the state hash and every field compared with ==).
#include "edit.h"
#include "edit_history.h"
#include "scene.h"
#include "settings_table.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using json = nlohmann::json;

// Three blocks: "a" (1 kg), "b" (2 kg), a static floor "floor".
Scene threeBlocks() {
    const SceneResult r = parseScene(R"({"name": "t", "world": {"gravity": [0, -9.81]},
        "blocks": [
          {"name": "a", "position": [4, 6], "size": 1, "velocity": [3, 0], "mass": 1},
          {"name": "b", "position": [8, 6], "size": 1, "mass": 2},
          {"name": "floor", "position": [10, 0.5], "size": [20, 1], "mass": "static"}]})",
                                     "t.json");
    EXPECT_TRUE(r.scene) << r.error.text();
    return *r.scene;
}

struct Editable {
    World world;
    std::vector<BlockLabel> labels;
    explicit Editable(const Scene& scene) : world(makeWorld(scene)) {
        for (const BlockDef& def : scene.blocks) labels.push_back({def.name, def.color});
    }
    EditTarget target() { return {world, labels}; }
};

bool sameBlock(const Block& a, const Block& b) {
    return a.position == b.position && a.size == b.size && a.velocity == b.velocity &&
           a.mass == b.mass && a.force == b.force && a.kind == b.kind && a.friction == b.friction;
}

bool sameWorld(const World& a, const World& b) {
    if (a.blocks.size() != b.blocks.size() || stateHash(a) != stateHash(b)) return false;
    for (std::size_t i = 0; i < a.blocks.size(); ++i)
        if (!sameBlock(a.blocks[i], b.blocks[i])) return false;
    return settings_table::sameAllSettings(a.settings, b.settings);
}

TEST(Edit, SetsAWorldKeyWithinItsLimitsAndUndoesIt) {
    Editable e(threeBlocks());
    const World start = e.world;
    const ApplyResult r = applyEdit(e.target(), Edit::setWorld("bounciness", 0.5));
    ASSERT_TRUE(r.applied) << r.error.text();
    EXPECT_EQ(e.world.settings.bounciness, 0.5);
    EXPECT_TRUE(undoEdit(e.target(), *r.applied).empty());
    EXPECT_TRUE(sameWorld(e.world, start));
    EXPECT_TRUE(redoEdit(e.target(), *r.applied).empty());
    EXPECT_EQ(e.world.settings.bounciness, 0.5);
}

TEST(Edit, RefusesAValueOutsideTheTableAndChangesNothing) {
    Editable e(threeBlocks());
    const World start = e.world;
    ApplyResult r = applyEdit(e.target(), Edit::setWorld("bounciness", 2));
    EXPECT_FALSE(r.applied);
    EXPECT_EQ(r.error.text(), "bounciness: must be from 0 to 1, not 2");
    r = applyEdit(e.target(), Edit::setWorld("method", "fast"));
    EXPECT_EQ(r.error.key, "method");
    EXPECT_NE(r.error.message.find("\"turn-based\""), std::string::npos) << r.error.message;
    r = applyEdit(e.target(), Edit::setWorld("rest_speed", 1)); // the engine's own: no key
    EXPECT_EQ(r.error.text(), "rest_speed: no such world key");
    r = applyEdit(e.target(), Edit::setBlock({-1, "b"}, "mass", -4));
    EXPECT_EQ(r.error.key, "b.mass");
    EXPECT_NE(r.error.message.find("1e-15"), std::string::npos) << r.error.message;
    EXPECT_TRUE(sameWorld(e.world, start));
}

TEST(Edit, ASetOfNamesReplacesTheSetWhole) {
    Editable e(threeBlocks());
    ASSERT_TRUE(applyEdit(e.target(), Edit::setWorld("mistakes", json{"discrete"})).applied);
    ASSERT_TRUE(
        applyEdit(e.target(), Edit::setWorld("mistakes", json{"discrete", "move-back"})).applied);
    EXPECT_TRUE(e.world.settings.has(Mistake::Discrete));
    EXPECT_TRUE(e.world.settings.has(Mistake::MoveBack));
    ASSERT_TRUE(applyEdit(e.target(), Edit::setWorld("mistakes", json::array())).applied);
    EXPECT_EQ(e.world.settings.mistakes, 0);
}

TEST(Edit, FindsABlockByNameOrPlaceAndSaysWhenItCannot) {
    Editable e(threeBlocks());
    ASSERT_TRUE(applyEdit(e.target(), Edit::setBlock({-1, "b"}, "mass", 4)).applied);
    EXPECT_EQ(e.world.blocks[1].mass, 4.0);
    ASSERT_TRUE(applyEdit(e.target(), Edit::setBlock({0, ""}, "mass", 3)).applied);
    EXPECT_EQ(e.world.blocks[0].mass, 3.0);
    ApplyResult r = applyEdit(e.target(), Edit::setBlock({-1, "c"}, "mass", 1));
    EXPECT_EQ(r.error.text(), "c.mass: no block is named \"c\"");
    r = applyEdit(e.target(), Edit::setBlock({7, ""}, "mass", 1));
    EXPECT_EQ(r.error.text(), "blocks[7].mass: no such block: the world has 3 blocks");
    e.labels[1].name = "a";
    r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "mass", 1));
    EXPECT_EQ(r.error.text(),
              "a.mass: 2 blocks are named \"a\": name it by its place, e.g. blocks[0]");
    r = applyEdit(e.target(), Edit::setBlock({0, ""}, "weight", 1));
    EXPECT_EQ(r.error.text(), "blocks[0].weight: unknown key");
}

TEST(Edit, AMassOnAStaticBlockMakesItDynamicAndUndoPutsItBack) {
    Editable e(threeBlocks());
    const World start = e.world;
    const ApplyResult r = applyEdit(e.target(), Edit::setBlock({-1, "floor"}, "mass", 5));
    ASSERT_TRUE(r.applied) << r.error.text();
    EXPECT_EQ(e.world.blocks[2].kind, BodyKind::Dynamic);
    EXPECT_EQ(e.world.blocks[2].mass, 5.0);
    ASSERT_TRUE(undoEdit(e.target(), *r.applied).empty());
    EXPECT_TRUE(sameWorld(e.world, start));
    // And a moving block made static stops; undone, it has its velocity back.
    const ApplyResult s = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "mass", "static"));
    ASSERT_TRUE(s.applied);
    EXPECT_EQ(e.world.blocks[0].velocity, Vec2{});
    EXPECT_TRUE(std::isinf(e.world.blocks[0].mass));
    ASSERT_TRUE(undoEdit(e.target(), *s.applied).empty());
    EXPECT_TRUE(sameWorld(e.world, start));
}

TEST(Edit, UndoPutsBackOnlyWhatTheEditChanged) {
    Editable e(threeBlocks());
    const ApplyResult r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "mass", 4));
    ASSERT_TRUE(r.applied);
    for (int i = 0; i < 30; ++i) e.world.step();
    const Vec2 position = e.world.blocks[0].position, velocity = e.world.blocks[0].velocity;
    ASSERT_TRUE(undoEdit(e.target(), *r.applied).empty());
    EXPECT_EQ(e.world.blocks[0].mass, 1.0);
    EXPECT_EQ(e.world.blocks[0].position, position); // not moved back to where it was
    EXPECT_EQ(e.world.blocks[0].velocity, velocity);
}

TEST(Edit, ABlocksOwnFrictionIsSetAndGivenBackToTheWorldsByNull) {
    Editable e(threeBlocks());
    ASSERT_TRUE(applyEdit(e.target(), Edit::setBlock({-1, "a"}, "friction", 0.4)).applied);
    EXPECT_EQ(e.world.blocks[0].friction, 0.4);
    const ApplyResult r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "friction", nullptr));
    ASSERT_TRUE(r.applied);
    EXPECT_LT(e.world.blocks[0].friction, 0.0); // the world's
    ASSERT_TRUE(undoEdit(e.target(), *r.applied).empty());
    EXPECT_EQ(e.world.blocks[0].friction, 0.4);
}

TEST(Edit, AMoveOntoAnotherBlockOrOutOfTheWorldIsRefused) {
    Editable e(threeBlocks());
    const World start = e.world;
    ApplyResult r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "position", json{7.5, 6}));
    EXPECT_EQ(r.error.text(), "a.position: overlaps blocks[1]");
    r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "position", json{19.8, 6}));
    EXPECT_EQ(r.error.text(), "a.position: sticks out of the world bounds [0.0, 0.0, 20.0, 12.0]");
    r = applyEdit(e.target(), Edit::setBlock({-1, "a"}, "size", json{8, 1}));
    EXPECT_EQ(r.error.text(), "a.size: overlaps blocks[1]");
    EXPECT_TRUE(sameWorld(e.world, start));
    // Touching is fine.
    EXPECT_TRUE(applyEdit(e.target(), Edit::setBlock({-1, "a"}, "position", json{7, 6})).applied);
}

TEST(Edit, AddAndRemoveAreUndoneExactlyNamesIncluded) {
    Editable e(threeBlocks());
    const World start = e.world;
    const auto labels = e.labels;
    const ApplyResult add = applyEdit(
        e.target(), Edit::add({{"name", "c"}, {"position", {12, 6}}, {"size", 1}, {"mass", 3}}));
    ASSERT_TRUE(add.applied) << add.error.text();
    ASSERT_EQ(e.world.blocks.size(), 4u);
    EXPECT_EQ(e.labels[3].name, "c");
    const ApplyResult remove = applyEdit(e.target(), Edit::remove({-1, "a"}));
    ASSERT_TRUE(remove.applied);
    EXPECT_EQ(e.labels[0].name, "b");
    ASSERT_TRUE(undoEdit(e.target(), *remove.applied).empty());
    ASSERT_TRUE(undoEdit(e.target(), *add.applied).empty());
    EXPECT_TRUE(sameWorld(e.world, start));
    ASSERT_EQ(e.labels.size(), labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) EXPECT_EQ(e.labels[i].name, labels[i].name);
    // An added block must fit.
    const ApplyResult onTop = applyEdit(e.target(), Edit::add({{"position", {8, 6}}, {"size", 1}}));
    EXPECT_EQ(onTop.error.text(), "add: overlaps blocks[1]");
    EXPECT_EQ(e.world.blocks.size(), 3u);
    const ApplyResult bad = applyEdit(e.target(), Edit::add({{"position", {8, 6}}}));
    EXPECT_EQ(bad.error.text(), "add: missing \"size\"");
}

TEST(Edit, AnUndoThatNoLongerFitsIsRefused) {
    Editable e(threeBlocks());
    const ApplyResult move =
        applyEdit(e.target(), Edit::setBlock({-1, "a"}, "position", json{12, 6}));
    ASSERT_TRUE(move.applied);
    ASSERT_TRUE(applyEdit(e.target(), Edit::setBlock({-1, "b"}, "position", json{4, 6})).applied);
    const EditError error = undoEdit(e.target(), *move.applied);
    EXPECT_EQ(error.text(), "a.position: overlaps blocks[1]");
    EXPECT_EQ(e.world.blocks[0].position, (Vec2{12, 6})); // not moved
}

TEST(EditHistory, UndoRedoAndAGestureIsOneStep) {
    Editable e(threeBlocks());
    EditHistory h;
    for (double c : {0.9, 0.8, 0.7})
        ASSERT_TRUE(h.apply(e.target(), Edit::setWorld("bounciness", c), 5, true).applied);
    ASSERT_TRUE(h.apply(e.target(), Edit::setBlock({1, ""}, "mass", 4), 5).applied);
    // The three values of the slider at one frame: one line, one undo step.
    ASSERT_EQ(h.journal().size(), 2u);
    EXPECT_EQ(*h.journal()[0].edit.value, 0.7);
    EXPECT_EQ(h.journal()[1].edit.block.name, "b"); // the journal names the block
    UndoResult u = h.undo(e.target(), 6);
    ASSERT_TRUE(u.edit);
    EXPECT_EQ(e.world.blocks[1].mass, 2.0);
    u = h.undo(e.target(), 6);
    ASSERT_TRUE(u.edit);
    EXPECT_EQ(u.edit->settingsBefore.bounciness, 1.0);
    EXPECT_EQ(u.edit->settingsAfter.bounciness, 0.7);
    EXPECT_EQ(e.world.settings.bounciness, 1.0);
    EXPECT_FALSE(h.undo(e.target(), 6).edit); // nothing more
    ASSERT_TRUE(h.redo(e.target(), 7).edit);
    EXPECT_EQ(e.world.settings.bounciness, 0.7);
    // A new edit empties the redo stack.
    ASSERT_TRUE(h.apply(e.target(), Edit::setWorld("bounciness", 0.2), 8).applied);
    EXPECT_FALSE(h.canRedo());
    ASSERT_EQ(h.journal().size(), 6u);
    EXPECT_EQ(h.journal()[2].what, JournalEntry::What::Undo);
    EXPECT_EQ(h.journal()[4].what, JournalEntry::What::Redo);
}

TEST(EditHistory, AGestureAcrossFramesKeepsEachValueAsOneUndoStep) {
    Editable e(threeBlocks());
    EditHistory h;
    ASSERT_TRUE(h.apply(e.target(), Edit::setWorld("bounciness", 0.9), 1, true).applied);
    ASSERT_TRUE(h.apply(e.target(), Edit::setWorld("bounciness", 0.8), 2, true).applied);
    ASSERT_EQ(h.journal().size(), 2u);
    EXPECT_FALSE(h.journal()[0].continues);
    EXPECT_TRUE(h.journal()[1].continues);
    ASSERT_TRUE(h.undo(e.target(), 3).edit);
    EXPECT_EQ(e.world.settings.bounciness, 1.0);
    EXPECT_FALSE(h.canUndo());
}

} // namespace
