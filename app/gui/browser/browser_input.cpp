#include "browser_input.h"

#include <algorithm>
#include <cmath>

namespace {

double notches(double delta, int deltaMode) {
    if (!std::isfinite(delta)) return 0.0;
    double n = delta; // WheelDeltaMode::Page: a page is a notch
    if (deltaMode == static_cast<int>(WheelDeltaMode::Pixel))
        n = delta / kWheelPixelsPerNotch;
    else if (deltaMode == static_cast<int>(WheelDeltaMode::Line))
        n = delta / kWheelLinesPerNotch;
    return std::clamp(-n, -kMaxWheelNotches, kMaxWheelNotches); // the browser's down is GLFW's -1
}

} // namespace

bool wheelPans(double deltaX, double deltaY, int deltaMode, bool ctrl) {
    if (ctrl || deltaMode != static_cast<int>(WheelDeltaMode::Pixel)) return false;
    if (!std::isfinite(deltaX) || !std::isfinite(deltaY)) return false;
    return deltaX != 0.0 || std::abs(deltaY) < 0.5 * kWheelPixelsPerNotch;
}

Vec2 wheelNotches(double deltaX, double deltaY, int deltaMode) {
    return {notches(deltaX, deltaMode), notches(deltaY, deltaMode)};
}
