// ShapeBatch: coloured triangles in world space (metres), built on the CPU each frame and drawn
// in one call: grid lines, the arena, arrows, trails. Pure logic; the renderer uploads it.
#pragma once

#include "camera.h"
#include "palette.h"
#include "vec2.h"

#include <vector>

struct ShapeVertex {
    float x, y;       // m
    float r, g, b, a; // colour
};

class ShapeBatch {
  public:
    void clear() {
        vertices_.clear();
        segments_.clear();
    }
    const std::vector<ShapeVertex>& vertices() const { return vertices_; }

    void triangle(Vec2 a, Vec2 b, Vec2 c, const Color& color);
    // An axis-aligned rectangle from `min` to `max`.
    void rect(Vec2 min, Vec2 max, const Color& color);
    // A segment of the given width (m); the two ends may have different colours (trails fade).
    void line(Vec2 a, Vec2 b, double width, const Color& colorA, const Color& colorB);
    void line(Vec2 a, Vec2 b, double width, const Color& color) { line(a, b, width, color, color); }
    // A shaft of `width` from `from` to `to` with a head of length `head` (m); nothing when the
    // arrow is shorter than a tiny fraction of the head.
    void arrow(Vec2 from, Vec2 to, double width, double head, const Color& color);
    // A segment drawn as one GL line primitive (GL_LINES, of the width set when drawing): on
    // llvmpipe about a third of the cost of the two triangles of line().
    void segment(Vec2 a, Vec2 b, const Color& colorA, const Color& colorB);
    void segment(Vec2 a, Vec2 b, const Color& color) { segment(a, b, color, color); }
    // An arrow whose shaft is a segment (the batch's line width) and whose head is a triangle of
    // length `head` (m).
    void lineArrow(Vec2 from, Vec2 to, double head, const Color& color);
    const std::vector<ShapeVertex>& segmentVertices() const { return segments_; }

  private:
    void vertex(Vec2 p, const Color& c);
    std::vector<ShapeVertex> vertices_;
    std::vector<ShapeVertex> segments_; // pairs of ends
};

// The segments (pairs of ends, as segmentVertices()) as triangles, for a GL context without wide
// lines (WebGL 2 draws lines 1 px wide only). Each segment becomes the quad OpenGL rasterises for a
// line `widthPx` wide: both ends moved half the width either way along the minor axis (up and
// down for a line more horizontal than vertical), so the look is the desktop's. `pixelsPerMetre`
// is the framebuffer's scale. wideLineQuadVertices says how many vertices (six per segment);
// writeWideLineQuads writes them to `out` (room for that many, no alignment needed: the
// renderer's upload, without a copy between).
std::size_t wideLineQuadVertices(const std::vector<ShapeVertex>& segments, double pixelsPerMetre);
void writeWideLineQuads(const std::vector<ShapeVertex>& segments, double widthPx,
                        double pixelsPerMetre, void* out);

// Whether a block `widthPx` x `heightPx` on screen, centred at `centre` (screen pixels), is drawn
// as a point sprite rather than a quad: it is small (the sprite, a square of its larger side
// plus 2 px, is within `maxPointPx`), not far from square (the sprite's pixels outside the block
// are discarded, and cost), and wholly inside `screen` with 2 px to spare (a point is clipped
// away whole once its centre leaves the view).
bool drawsAsPointSprite(double widthPx, double heightPx, Vec2 centre, const ScreenRect& screen,
                        double maxPointPx);
