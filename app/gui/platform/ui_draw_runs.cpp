#include "ui_draw_runs.h"

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
    // 1. Maximal stretches of one kind, with the pixels of the solid ones.
    std::vector<float> solidPixels;
    for (unsigned k = 0; k + 2 < indexCount; k += 3) {
        const ImDrawVert& a = vertices[indices[k]];
        const ImDrawVert& b = vertices[indices[k + 1]];
        const ImDrawVert& c = vertices[indices[k + 2]];
        const bool solid = isWhite(a, whiteUv) && isWhite(b, whiteUv) && isWhite(c, whiteUv);
        if (runs.size() > start && runs.back().solid == solid) {
            runs.back().indexCount += 3;
        } else {
            runs.push_back({indexBase + k, 3, solid});
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
