// What the mouse does in the scene: click selects, left-drag moves a block (the simulation pauses;
// it follows the cursor to the nearest free spot, never onto another block; the whole drag is
// one edit), right-drag flings (velocity from the drag vector), middle-drag pans, double-click on
// empty space adds a block. Every change is an edit through the session's door (apply). Pure logic
// on the simulation session, the view and screen positions (no ImGui), so it is tested without GL;
// scene_view.cpp feeds it ImGui's mouse state.
#pragma once

#include "vec2.h"

struct SimulationSession;
struct View;
struct World;

enum class MouseButton { Left, Right, Middle };

// Fling gain: velocity (m/s) per metre of right-drag.
constexpr double kFlingGain = 2.0;

struct MouseTool {
    enum class Mode { Idle, Dragging, Flinging, Panning };
    Mode mode = Mode::Idle;
    int block = -1;     // the block being dragged or flung
    Vec2 grabOffset;    // m, block centre minus the cursor at the press
    Vec2 startPosition; // m, where the dragged block was (restored when no spot is free)
    Vec2 pressWorld;    // m, the cursor at the press
    Vec2 cursorWorld;   // m, the cursor now
    Vec2 lastScreen;    // px, for panning

    // The simulation waits while a block is held.
    bool holdsSimulation() const { return mode == Mode::Dragging || mode == Mode::Flinging; }
    // The velocity a release would give the flung block.
    Vec2 flingVelocity() const { return (cursorWorld - pressWorld) * kFlingGain; }
};

// The mouse's buttons over the scene: picks, drags and flings blocks of `sim` seen through
// `view`'s camera, pans the camera.
void mousePress(MouseTool& m, SimulationSession& sim, const View& view, MouseButton button,
                Vec2 screen, bool doubleClick);
// The block a press at `screen` (px) would take (a few pixels' tolerance), or -1.
int blockAtScreen(const World& world, const View& view, Vec2 screen);
void mouseMove(MouseTool& m, SimulationSession& sim, View& view, Vec2 screen);
void mouseRelease(MouseTool& m, SimulationSession& sim, View& view, MouseButton button,
                  Vec2 screen);
// Wheel zoom about the cursor: `steps` notches (positive zooms in).
void mouseWheel(View& view, Vec2 screen, double steps);
// A two-finger touch gesture: pans by the move of the fingers' midpoint (`from` to `to`, screen
// pixels) and zooms about its new place by the change of their distance (`spreadRatio`).
void touchPanZoom(View& view, Vec2 from, Vec2 to, double spreadRatio);
