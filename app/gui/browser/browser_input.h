// What the browser's input events mean to the app, as pure logic (the page passes the raw
// numbers; tested in tests/app).
#pragma once

#include "vec2.h"

// A wheel event's deltaMode (WheelEvent.DOM_DELTA_*).
enum class WheelDeltaMode { Pixel = 0, Line = 1, Page = 2 };

// Notches of a mouse wheel as the desktop's GLFW reports them: one notch is 1, positive y up
// (away from the user: zoom in), positive x left. The browser reports about 100 px per notch in
// pixel mode (Chromium, Safari; Firefox with smooth scrolling), 3 lines in line mode (Firefox)
// and 1 page in page mode, positive down and right; a touchpad's smooth scroll comes as many
// small pixel deltas, so it zooms smoothly in fractions of a notch. One event gives at most
// kMaxWheelNotches either way; NaN or infinite deltas give none.
Vec2 wheelNotches(double deltaX, double deltaY, int deltaMode);
// Whether a wheel event is a touchpad's two-finger scroll, which pans the scene as two fingers on
// a touch screen do, rather than a mouse wheel's notch, which zooms: in pixel mode, sideways
// (deltaX not 0) or less than half a notch. With Ctrl (`ctrl`: what browsers send for a
// touchpad's pinch, and Ctrl+wheel) it zooms. (A free-spinning mouse wheel's small steps pan too:
// no event says which device sent it.)
bool wheelPans(double deltaX, double deltaY, int deltaMode, bool ctrl);
inline constexpr double kWheelPixelsPerNotch = 100.0;
inline constexpr double kWheelLinesPerNotch = 3.0;
inline constexpr double kMaxWheelNotches = 10.0;
