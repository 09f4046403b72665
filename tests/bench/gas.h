// The benchmark gas (SPEC, acceptance numbers): squares of 0.5 m on a 1 m grid, speeds up to
// 3 m/s in random directions, no gravity, C = 1, dt = 1/60, in a square box just large enough.
#pragma once

#include "scene.h"

#include <cstdint>

Scene makeGasScene(int count, std::uint32_t seed = 1);
// The gas as a world stepped by `method`, without the overlap measurement (not part of a step).
World makeGas(int count, Method method, std::uint32_t seed = 1);
