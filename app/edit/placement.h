// Picking and placing blocks without overlap: what the mouse does to the world, as pure functions
// (tested without GL). "Overlap" means positive area, as in the scene format: touching is fine.
#pragma once

#include "vec2.h"
#include "world.h"

#include <optional>

// The gap (m) left between a placed block and the block it is placed beside, so that rounding
// never turns "touching" into a tiny overlap.
constexpr double kPlacementGap = 1e-6;

// Index of the topmost (last drawn) block containing `p`, grown by `tolerance` metres on each
// side so thin blocks can be picked; -1 when none.
int pickBlock(const World& world, Vec2 p, double tolerance);

// `position` moved just enough that a block of `size` lies inside the world's bounds (centred
// when it is larger than the bounds).
Vec2 clampIntoBounds(const Bounds& bounds, Vec2 position, Vec2 size);

// True when a block of `size` at `position` overlaps any block other than `ignore` (-1: none).
bool overlapsAnyBlock(const World& world, int ignore, Vec2 position, Vec2 size);

// Where a block of `size` (block `ignore` of the world being moved, or -1 for a new block) can go
// near `desired`: `desired` itself (clamped into the bounds) when free, otherwise the nearest free
// spot beside the blocks it would overlap. std::nullopt when no free spot is found nearby.
std::optional<Vec2> placeWithoutOverlap(const World& world, int ignore, Vec2 desired, Vec2 size);
