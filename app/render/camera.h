// Camera: the mapping between world space (metres, y up) and screen space (pixels, y down, origin
// at the top-left of the window). Pure logic: no GL, so it is tested on its own.
#pragma once

#include "vec2.h"
#include "world.h"

// A rectangle in screen pixels: top-left corner and size.
struct ScreenRect {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;

    bool contains(Vec2 p) const {
        return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height;
    }
    Vec2 centre() const { return {x + width * 0.5, y + height * 0.5}; }
};

// A clip-space transform for the shaders: clip = world * scale + offset, per axis.
struct ClipTransform {
    float scaleX = 1.0f, scaleY = 1.0f;
    float offsetX = 0.0f, offsetY = 0.0f;
};

class Camera {
  public:
    static constexpr double kMinPixelsPerMetre = 1.0;
    static constexpr double kMaxPixelsPerMetre = 2000.0;

    // The part of the window the scene is drawn into.
    void setViewport(const ScreenRect& viewport) { viewport_ = viewport; }
    const ScreenRect& viewport() const { return viewport_; }

    Vec2 centre() const { return centre_; }
    double pixelsPerMetre() const { return pixelsPerMetre_; }
    void setCentre(Vec2 centre) { centre_ = centre; }
    void setPixelsPerMetre(double ppm);

    // (In the header: called for every block, arrow and label several times a frame.)
    Vec2 worldToScreen(Vec2 world) const {
        const Vec2 c = viewport_.centre();
        return {c.x + (world.x - centre_.x) * pixelsPerMetre_,
                c.y - (world.y - centre_.y) * pixelsPerMetre_};
    }
    Vec2 screenToWorld(Vec2 screen) const;
    double metresToPixels(double metres) const { return metres * pixelsPerMetre_; }
    double pixelsToMetres(double pixels) const { return pixels / pixelsPerMetre_; }

    // Shows the whole of `bounds` (plus `marginPx` around it) in the viewport, centred.
    void fit(const Bounds& bounds, double marginPx);
    // Multiplies the zoom by `factor`, keeping the world point under `screenPoint` where it is.
    void zoomAbout(Vec2 screenPoint, double factor);
    // Moves the view with the cursor: the world follows a drag of `deltaPx` screen pixels.
    void panPixels(Vec2 deltaPx);

    // The world-to-clip transform for a framebuffer of the given size in screen pixels.
    ClipTransform clipTransform(double displayWidth, double displayHeight) const;

  private:
    ScreenRect viewport_{0.0, 0.0, 1280.0, 720.0};
    Vec2 centre_{10.0, 6.0};
    double pixelsPerMetre_ = 50.0;
};

// Grid spacing (m): 1, 2, 5, 10, 20, 50, ... whichever first puts lines at least `minPx` apart.
double gridSpacing(double pixelsPerMetre, double minPx);
