// A player the keys control (the lecture's "Application: Platformer": physics-based movement):
// a scene names one dynamic block (docs/scene-format.md, "player"), left/right push it with a
// force and up makes it jump, only when it stands on something. The same rule for the window, the
// offscreen renderer and the headless lesson runner.
#pragma once

#include "world.h"

#include <vector>

struct PlayerDef {
    int block = -1;     // index of the controlled block (dynamic)
    double force = 0.0; // N: left/right push it with this force along x
    double jump = 0.0;  // m/s: up gives it this speed upward, relative to what it stands on

    bool operator==(const PlayerDef& o) const {
        return block == o.block && force == o.force && jump == o.jump;
    }
};

// The keys held this frame.
struct PlayerKeys {
    bool left = false, right = false, up = false;
    bool any() const { return left || right || up; }
};

// A scripted key (a lesson step's "input": docs/lesson-format.md): `keys` held from `at` (s
// since the step began) for `duration` s; a press lasts one frame (duration 0).
struct ScriptedKeys {
    double at = 0.0;       // s
    double duration = 0.0; // s; 0: a press, held for the one frame that starts at or after `at`
    PlayerKeys keys;
};
// The keys a script holds in the frame of length dt that starts at time t (s since the step
// began): a hold in the frames starting in [at, at + duration), a press in the first frame
// starting at or after `at` (times within 1e-9 s count as equal: they are sums of dt).
PlayerKeys scriptedKeys(const std::vector<ScriptedKeys>& script, double t, double dt);

// What block i stands on: a block whose top face its bottom face touches (within
// kTouchTolerance, overlapping along x), kFloorBelow for the bottom wall, or kNothingBelow (it is
// in mid-air). Read at the end of the last step: its contact below in that step.
constexpr int kNothingBelow = -1;
constexpr int kFloorBelow = -2;
int standsOn(const World& world, int i);

// The push the keys give the player (N, along x): its move force, to the right for right, to the
// left for left, none for both or neither (or a block that is not dynamic). What
// applyPlayerKeys returns and the force arrow shows.
Vec2 playerPush(const World& world, const PlayerDef& player, PlayerKeys keys);

// What the keys do this frame, before the step: the push along x (N, to be added to the block's
// own force for this frame only: F = m·a) and, when up is held and the player stands on
// something, the jump: its vertical velocity becomes that body's plus `jump` (in mid-air up does
// nothing). Returns the push.
Vec2 applyPlayerKeys(World& world, const PlayerDef& player, PlayerKeys keys);

// One frame with the keys: applyPlayerKeys, then World::step with the push added to the
// block's force, which is then restored (the push is not part of the state).
StepStats stepWithPlayer(World& world, const PlayerDef& player, PlayerKeys keys,
                         std::vector<CollisionRecord>* log = nullptr);
