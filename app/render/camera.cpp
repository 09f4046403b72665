#include "camera.h"

#include <algorithm>

void Camera::setPixelsPerMetre(double ppm) {
    if (!(ppm > 0.0)) return; // rejects NaN as well
    pixelsPerMetre_ = std::clamp(ppm, kMinPixelsPerMetre, kMaxPixelsPerMetre);
}

Vec2 Camera::screenToWorld(Vec2 screen) const {
    const Vec2 c = viewport_.centre();
    return {centre_.x + (screen.x - c.x) / pixelsPerMetre_,
            centre_.y - (screen.y - c.y) / pixelsPerMetre_};
}

void Camera::fit(const Bounds& bounds, double marginPx) {
    const double w = bounds.max.x - bounds.min.x;
    const double h = bounds.max.y - bounds.min.y;
    centre_ = (bounds.min + bounds.max) * 0.5;
    const double availW = std::max(1.0, viewport_.width - 2.0 * marginPx);
    const double availH = std::max(1.0, viewport_.height - 2.0 * marginPx);
    if (w > 0.0 && h > 0.0) setPixelsPerMetre(std::min(availW / w, availH / h));
}

void Camera::zoomAbout(Vec2 screenPoint, double factor) {
    if (!(factor > 0.0)) return;
    const Vec2 anchor = screenToWorld(screenPoint);
    setPixelsPerMetre(pixelsPerMetre_ * factor);
    // Move the centre so that `anchor` maps back to `screenPoint`.
    const Vec2 c = viewport_.centre();
    centre_.x = anchor.x - (screenPoint.x - c.x) / pixelsPerMetre_;
    centre_.y = anchor.y + (screenPoint.y - c.y) / pixelsPerMetre_;
}

void Camera::panPixels(Vec2 deltaPx) {
    centre_.x -= deltaPx.x / pixelsPerMetre_;
    centre_.y += deltaPx.y / pixelsPerMetre_;
}

ClipTransform Camera::clipTransform(double displayWidth, double displayHeight) const {
    // screen = c + (world - centre) * ppm (y flipped); clip.x = screen.x / W * 2 - 1 and
    // clip.y = 1 - screen.y / H * 2.
    const Vec2 c = viewport_.centre();
    const double sx = 2.0 * pixelsPerMetre_ / displayWidth;
    const double sy = 2.0 * pixelsPerMetre_ / displayHeight;
    ClipTransform t;
    t.scaleX = static_cast<float>(sx);
    t.scaleY = static_cast<float>(sy);
    t.offsetX = static_cast<float>((c.x - centre_.x * pixelsPerMetre_) / displayWidth * 2.0 - 1.0);
    t.offsetY = static_cast<float>(1.0 - (c.y + centre_.y * pixelsPerMetre_) / displayHeight * 2.0);
    return t;
}

double gridSpacing(double pixelsPerMetre, double minPx) {
    double step = 1.0;
    const double factors[3] = {2.0, 2.5, 2.0};
    for (int i = 0; step * pixelsPerMetre < minPx && i < 40; ++i) step *= factors[i % 3];
    return step;
}
