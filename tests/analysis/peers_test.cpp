// The peers read the scene through the settings table: every world key has its use (PeerUse), a
// peer is set up with the Set rows only, and what it runs without is said (app/analysis/peers.h).
#include "peers.h"
#include "tradeoff.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

TEST(PeerKeys, EveryWorldKeyOfTheSettingsTableHasAPeerUse) {
    // A new world key fails here until peers.cpp says what the peers make of it.
    for (const settings_table::WorldKey& row : settings_table::worldKeys())
        EXPECT_TRUE(peerUse(row).has_value()) << row.key;
}

TEST(PeerKeys, WhatThePeersLackIsSaid) {
    WorldSettings s = defaultWorldSettings();
    EXPECT_TRUE(settingsPeersLack(s).empty());
    s.friction = 0.4;             // taken
    s.method = Method::TurnBased; // the peers' own
    EXPECT_TRUE(settingsPeersLack(s).empty());
    s.drag = 0.5; // no peer has drag
    EXPECT_EQ(settingsPeersLack(s), std::vector<std::string>{"drag 0.5 kg/m³"});
}

TEST(PeerKeys, TheTradeoffTableSaysWhatThePeersRanWithout) {
    TradeoffRow engine, peer;
    engine.engine = "perfect";
    peer.engine = "box2d";
    engine.scene = peer.scene = "friction_slide";
    engine.dt = peer.dt = 1.0 / 60;
    peer.lacks = {"drag 0.5 kg/m³"};
    std::ostringstream md;
    writeTradeoffMarkdown(md, {engine, peer});
    EXPECT_NE(md.str().find("The peers ran without drag 0.5 kg/m³"), std::string::npos) << md.str();
    std::ostringstream none;
    writeTradeoffMarkdown(none, {engine});
    EXPECT_EQ(none.str().find("ran without"), std::string::npos) << none.str();
}
