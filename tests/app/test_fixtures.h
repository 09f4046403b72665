// What the app's logic tests build in code, each in one place: scenes (a block in one line: its
// name, where it stands, its size and mass; a world without gravity, so that nothing moves unless
// a test moves it), the record of a wall hit, and a parsed command line.
#pragma once

#include "options.h"
#include "scene.h"
#include "stats.h"

#include <string>
#include <vector>

// A dynamic block at rest at `position` (m), of `size` (m) and `mass` (kg).
BlockDef testBlock(const std::string& name, Vec2 position, Vec2 size = {1.0, 1.0},
                   double mass = 1.0);
// A static block (a floor, a post) at `position` (m), of `size` (m).
BlockDef staticBlock(const std::string& name, Vec2 position, Vec2 size = {1.0, 1.0});
// A scene called `name` holding `blocks`, with gravity off.
Scene weightlessScene(const std::string& name, std::vector<BlockDef> blocks);

// Block `block` of `mass` (kg) hitting the right wall along x at t = 1.5 s, as the engine records
// it: 4 m/s before, C = 0.5, so -2 m/s after (u = 0, the wall's velocity).
CollisionRecord rightWallHit(int block, double mass);

// The app's options from a command line (args[0] the program's name), its length counted.
ParsedOptions parseCommandLine(const std::vector<const char*>& args);
