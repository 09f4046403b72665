#include "ui_draw_runs.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace {

bool isWhite(const ImDrawVert& v, ImVec2 white) {
    return v.uv.x == white.x && v.uv.y == white.y;
}

// Twice the signed area of a triangle, halved and made positive: its pixels on screen.
float pixelArea(ImVec2 a, ImVec2 b, ImVec2 c) {
    return 0.5f * std::fabs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

} // namespace

void splitIntoRuns(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned indexBase,
                   unsigned indexCount, ImVec2 whiteUv, float minSolidPixels,
                   std::vector<UiDrawRun>& runs) {
    const std::size_t start = runs.size();
    // 1. Maximal stretches of one kind, with the pixels of the solid ones (kept between calls:
    //    a frame splits a hundred commands, each would allocate it anew).
    static thread_local std::vector<float> solidPixels;
    solidPixels.clear();
    for (unsigned k = 0; k + 2 < indexCount; k += 3) {
        const ImDrawVert& a = vertices[indices[k]];
        const ImDrawVert& b = vertices[indices[k + 1]];
        const ImDrawVert& c = vertices[indices[k + 2]];
        const bool solid = isWhite(a, whiteUv) && isWhite(b, whiteUv) && isWhite(c, whiteUv);
        if (runs.size() > start && runs.back().solid == solid) {
            runs.back().indexCount += 3;
        } else {
            runs.push_back({indexBase + k, 3, solid, {}, 0});
            solidPixels.push_back(0.0f);
        }
        if (solid) solidPixels.back() += pixelArea(a.pos, b.pos, c.pos);
    }
    // 2. Small solid stretches join the textured ones (one stretch alone stays as it is: no
    //    draw call is saved by drawing it textured), then equal neighbours merge.
    const std::size_t count = runs.size() - start;
    if (count > 1) {
        for (std::size_t i = 0; i < count; ++i) {
            if (runs[start + i].solid && solidPixels[i] < minSolidPixels)
                runs[start + i].solid = false;
        }
    }
    std::size_t kept = start;
    for (std::size_t i = start; i < runs.size(); ++i) {
        if (kept > start && runs[kept - 1].solid == runs[i].solid)
            runs[kept - 1].indexCount += runs[i].indexCount;
        else
            runs[kept++] = runs[i];
    }
    runs.resize(kept);
}

namespace {

// How far inside its fan's edges a pixel's centre must be to count as surely covered: GL snaps
// vertices to a 256th of a pixel, and ImGui's arcs end a hair off their rectangle's sides.
constexpr float kSureMargin = 0.05f;

// The number of triangles of the fan starting at `indices[first]` (v, v+1, v+2), (v, v+2, v+3),
// ... within `count` indices, every vertex of one opaque colour; 0 when it is none.
unsigned fanTriangles(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned first,
                      unsigned count) {
    const unsigned v = indices[first];
    const ImU32 color = vertices[v].col;
    if ((color >> IM_COL32_A_SHIFT & 0xFF) != 0xFF) return 0;
    unsigned n = 0;
    for (unsigned k = first; k + 2 < first + count; k += 3, ++n) {
        if (indices[k] != v || indices[k + 1] != v + n + 1 || indices[k + 2] != v + n + 2) break;
        if (vertices[v + n + 1].col != color || vertices[v + n + 2].col != color) break;
    }
    return n;
}

// The sure pixels of the convex fan of `n` triangles on vertices v..v+n+1 (see findOpaqueFills),
// or an empty rectangle when the fan is not convex.
UiPixelRect surePixels(const ImDrawVert* fan, unsigned n, ImVec2 origin, ImVec2 scale) {
    const unsigned corners = n + 2;
    const auto at = [&](unsigned i) {
        return ImVec2((fan[i].pos.x - origin.x) * scale.x, (fan[i].pos.y - origin.y) * scale.y);
    };
    float minX = INFINITY, maxX = -INFINITY;
    for (unsigned i = 0; i < corners; ++i) {
        minX = std::min(minX, at(i).x);
        maxX = std::max(maxX, at(i).x);
    }
    // The rows where both sides are straight: between the corners on the leftmost and on the
    // rightmost column.
    float leftTop = INFINITY, leftBottom = -INFINITY, rightTop = INFINITY, rightBottom = -INFINITY;
    for (unsigned i = 0; i < corners; ++i) {
        const ImVec2 p = at(i);
        if (p.x <= minX + kSureMargin) {
            leftTop = std::min(leftTop, p.y);
            leftBottom = std::max(leftBottom, p.y);
        }
        if (p.x >= maxX - kSureMargin) {
            rightTop = std::min(rightTop, p.y);
            rightBottom = std::max(rightBottom, p.y);
        }
    }
    const float x0 = minX + kSureMargin, x1 = maxX - kSureMargin;
    const float y0 = std::max(leftTop, rightTop) + kSureMargin;
    const float y1 = std::min(leftBottom, rightBottom) - kSureMargin;
    if (x1 <= x0 || y1 <= y0) return {};
    // Convex, every turn the same way, and the rectangle's corners inside every edge: then the
    // rectangle lies inside the fan.
    float turn = 0.0f;
    for (unsigned i = 0; i < corners; ++i) {
        const ImVec2 a = at(i), b = at((i + 1) % corners), c = at((i + 2) % corners);
        const float cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        if (cross == 0.0f) continue;
        if (turn != 0.0f && (cross > 0.0f) != (turn > 0.0f)) return {};
        turn = cross;
    }
    if (turn == 0.0f) return {};
    for (unsigned i = 0; i < corners; ++i) {
        const ImVec2 a = at(i), b = at((i + 1) % corners);
        for (const ImVec2 p : {ImVec2(x0, y0), ImVec2(x1, y0), ImVec2(x0, y1), ImVec2(x1, y1)}) {
            const float side = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            if (side != 0.0f && (side > 0.0f) != (turn > 0.0f)) return {};
            if (side == 0.0f) return {};
        }
    }
    // Pixel i's centre is at i + 0.5.
    return {static_cast<int>(std::ceil(x0 - 0.5f)), static_cast<int>(std::ceil(y0 - 0.5f)),
            static_cast<int>(std::floor(x1 - 0.5f)) + 1,
            static_cast<int>(std::floor(y1 - 0.5f)) + 1};
}

} // namespace

void findOpaqueFills(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned indexBase,
                     ImVec2 origin, ImVec2 scale, int minPixels, std::vector<UiDrawRun>& runs) {
    static thread_local std::vector<UiDrawRun> out; // kept between calls, as in splitIntoRuns
    out.clear();
    for (const UiDrawRun& run : runs) {
        if (!run.solid) {
            out.push_back(run);
            continue;
        }
        const unsigned first = run.firstIndex - indexBase, end = first + run.indexCount;
        unsigned from = first; // the start of the plain solid triangles not yet emitted
        for (unsigned k = first; k < end;) {
            const unsigned n = fanTriangles(vertices, indices, k, end - k);
            UiPixelRect sure;
            if (n > 0) sure = surePixels(vertices + indices[k], n, origin, scale);
            const bool big =
                !sure.empty() &&
                static_cast<long>(sure.x1 - sure.x0) * (sure.y1 - sure.y0) >= minPixels;
            if (!big) {
                k += 3 * std::max(n, 1u);
                continue;
            }
            if (k > from) out.push_back({indexBase + from, k - from, true, {}, 0});
            out.push_back({indexBase + k, 3 * n, true, sure, vertices[indices[k]].col});
            k += 3 * n;
            from = k;
        }
        if (end > from) out.push_back({indexBase + from, end - from, true, {}, 0});
    }
    runs.swap(out);
}
