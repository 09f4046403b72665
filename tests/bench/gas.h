// The benchmark gas (docs/physics.md, what the engine is held to): squares of 0.5 m on a 1 m grid, speeds up to
// 3 m/s in random directions, no gravity, C = 1, dt = 1/60, in a square box just large enough.
#pragma once

#include "scene.h"

#include <cstdint>

Scene makeGasScene(int count, std::uint32_t seed = 1);
// The gas as a world stepped by `method`, without the overlap measurement (not part of a step).
World makeGas(int count, Method method, std::uint32_t seed = 1);
// Issue 13's event storm, as `tools/make_gas_scene.py 40 25 0.25 1e9` lays it out: 1,000 squares
// of 0.25 m on a 40 x 25 grid in 20 m x 12 m, speeds up to 1e9 m/s in random directions, no
// gravity, C = 1, dt = 1/60, perfect method: every frame ends at the event cap.
World makeStorm(std::uint32_t seed = 1);
