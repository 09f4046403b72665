#include "shape_batch.h"

#include <algorithm>
#include <cmath>
#include <cstring>

void ShapeBatch::vertex(Vec2 p, const Color& c) {
    vertices_.push_back({static_cast<float>(p.x), static_cast<float>(p.y), c.r, c.g, c.b, c.a});
}

void ShapeBatch::triangle(Vec2 a, Vec2 b, Vec2 c, const Color& color) {
    vertex(a, color);
    vertex(b, color);
    vertex(c, color);
}

void ShapeBatch::rect(Vec2 min, Vec2 max, const Color& color) {
    triangle(min, {max.x, min.y}, max, color);
    triangle(min, max, {min.x, max.y}, color);
}

void ShapeBatch::line(Vec2 a, Vec2 b, double width, const Color& colorA, const Color& colorB) {
    const Vec2 d = b - a;
    if (lengthSquared(d) <= 0.0) return;
    const Vec2 n = perpendicular(normalized(d)) * (width * 0.5);
    vertex(a - n, colorA);
    vertex(a + n, colorA);
    vertex(b + n, colorB);
    vertex(a - n, colorA);
    vertex(b + n, colorB);
    vertex(b - n, colorB);
}

namespace {

// The head of an arrow from `from` to `to`: its base (where the shaft ends) and half its width.
struct ArrowHead {
    bool drawn = false;
    Vec2 base, side;
};

ArrowHead arrowHead(Vec2 from, Vec2 to, double head) {
    const Vec2 d = to - from;
    const double len = length(d);
    if (len < head * 0.05) return {};
    const Vec2 dir = d / len;
    const double headLen = std::min(head, len * 0.6);
    return {true, to - dir * headLen, perpendicular(dir) * (headLen * 0.55)};
}

} // namespace

void ShapeBatch::arrow(Vec2 from, Vec2 to, double width, double head, const Color& color) {
    const ArrowHead h = arrowHead(from, to, head);
    if (!h.drawn) return;
    line(from, h.base, width, color);
    triangle(to, h.base + h.side, h.base - h.side, color);
}

void ShapeBatch::lineArrow(Vec2 from, Vec2 to, double head, const Color& color) {
    const ArrowHead h = arrowHead(from, to, head);
    if (!h.drawn) return;
    segment(from, h.base, color);
    triangle(to, h.base + h.side, h.base - h.side, color);
}

void ShapeBatch::segment(Vec2 a, Vec2 b, const Color& colorA, const Color& colorB) {
    segments_.push_back(
        {static_cast<float>(a.x), static_cast<float>(a.y), colorA.r, colorA.g, colorA.b, colorA.a});
    segments_.push_back(
        {static_cast<float>(b.x), static_cast<float>(b.y), colorB.r, colorB.g, colorB.b, colorB.a});
}

bool drawsAsPointSprite(double widthPx, double heightPx, Vec2 centre, const ScreenRect& screen,
                        double maxPointPx) {
    const double side = std::max(widthPx, heightPx);
    const double reach = side * 0.5 + 2.0;
    return side + 2.0 <= maxPointPx && side <= 2.0 * std::min(widthPx, heightPx) + 4.0 &&
           centre.x - reach >= screen.x && centre.y - reach >= screen.y &&
           centre.x + reach <= screen.x + screen.width &&
           centre.y + reach <= screen.y + screen.height;
}

std::size_t wideLineQuadVertices(const std::vector<ShapeVertex>& segments, double pixelsPerMetre) {
    return pixelsPerMetre > 0.0 ? segments.size() / 2 * 6 : 0;
}

void writeWideLineQuads(const std::vector<ShapeVertex>& segments, double widthPx,
                        double pixelsPerMetre, void* out) {
    if (pixelsPerMetre <= 0.0) return;
    auto* to = static_cast<unsigned char*>(out);
    const auto half = static_cast<float>(0.5 * widthPx / pixelsPerMetre);
    for (std::size_t i = 0; i + 1 < segments.size(); i += 2) {
        const ShapeVertex& a = segments[i];
        const ShapeVertex& b = segments[i + 1];
        const bool xMajor = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
        const float ox = xMajor ? 0.0f : half, oy = xMajor ? half : 0.0f;
        ShapeVertex a0 = a, a1 = a, b0 = b, b1 = b;
        a0.x -= ox, a0.y -= oy, a1.x += ox, a1.y += oy;
        b0.x -= ox, b0.y -= oy, b1.x += ox, b1.y += oy;
        const ShapeVertex quad[6] = {a0, a1, b1, a0, b1, b0};
        std::memcpy(to, quad, sizeof quad);
        to += sizeof quad;
    }
}
