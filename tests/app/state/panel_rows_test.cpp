// The controls panel's columns (panel_rows.h) against the engine's settings table: every panel
// row names a real key, once, and its slider's ends are values the row's range takes; every scene
// key is in the panel's order; every block field the panel edits is a block key.
#include "panel_rows.h"
#include "settings_table.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

using settings_table::Kind;
using settings_table::WorldKey;

TEST(PanelRows, EveryRowNamesARealKeyOnce) {
    std::set<std::string> keys;
    std::set<int> places[2];
    for (const PanelRow& p : panelRows()) {
        EXPECT_TRUE(keys.insert(p.key).second) << p.key;
        const WorldKey* row = settings_table::findWorldKey(p.key);
        ASSERT_NE(row, nullptr) << "the panel names \"" << p.key << "\", no key of the table";
        EXPECT_EQ(panelRowOf(*row), &p);
        EXPECT_NE(std::string(p.label), "") << p.key;
        EXPECT_TRUE(places[static_cast<int>(p.section)].insert(p.place).second) << p.key;
        if (row->kind == Kind::Number || row->kind == Kind::Whole || row->kind == Kind::Pair) {
            // The slider's ends are values the range takes (what it shows, for a rate).
            const limits::Range& r = row->shown.asRate ? row->shown.rateRange : row->range;
            EXPECT_EQ(limits::violation(r, p.min), "") << p.key;
            EXPECT_EQ(limits::violation(r, p.max), "") << p.key;
            EXPECT_NE(std::string(p.format), "") << p.key;
        }
        if (row->kind == Kind::Pair) {
            EXPECT_NE(std::string(p.presetLabel), "") << p.key;
        }
    }
}

TEST(PanelRows, ThePanelsOrderHoldsEverySceneKeyPanelRowsFirst) {
    std::size_t sceneKeys = 0;
    for (const WorldKey& row : settings_table::worldKeys()) sceneKeys += row.inScene ? 1 : 0;
    const auto& order = panelOrder();
    EXPECT_EQ(order.size(), sceneKeys);
    bool offPanel = false;
    int lastRank = -1;
    for (const WorldKey* row : order) {
        const PanelRow* p = panelRowOf(*row);
        if (!p) {
            offPanel = true;
            continue;
        }
        EXPECT_FALSE(offPanel) << row->key << " after a row not on the panel";
        const int rank = static_cast<int>(p->section) * 1000 + p->place;
        EXPECT_GT(rank, lastRank) << row->key;
        lastRank = rank;
    }
    EXPECT_STREQ(order.front()->key, "method"); // the lecture's first choice leads
}

TEST(PanelRows, EveryBlockFieldIsABlockKey) {
    for (const BlockPanelRow& p : blockPanelRows()) {
        bool found = false;
        for (const settings_table::BlockKey& key : settings_table::blockKeys())
            found = found || std::strcmp(key.key, p.key) == 0;
        EXPECT_TRUE(found) << "the panel names block field \"" << p.key << "\", no block key";
        EXPECT_EQ(&blockPanelRow(p.key), &p);
        EXPECT_NE(std::string(p.label), "") << p.key;
        EXPECT_NE(std::string(p.format), "") << p.key;
    }
}
