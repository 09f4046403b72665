// Where the last frame's contacts were, over the scene: a filled dot on the touching faces of
// each collision the method resolved (lecture, "Collision Resolve"), a hollow ring for each
// resting contact of the rest rule, and, where friction acted, a short arrow along the face
// against the first body's sliding, or a bar once it holds (lecture, "Application: Platformer";
// the rule |dvt| <= mu·|dvn| is in resolve.h and the inspector prints its numbers). Marks only,
// no text: what they mean is the checkbox's tooltip, the numbers are the inspector's.
#include "app_frame.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace {

// The body `index` names as an axis-aligned box: a block, or a wall (a face of the bounds,
// extended outward: only its inner face and its span matter here).
struct Extent {
    Vec2 lo, hi;
};
Extent extentOf(const World& w, int index) {
    if (index >= 0) {
        const Block& b = w.blocks[static_cast<std::size_t>(index)];
        return {b.position - b.size * 0.5, b.position + b.size * 0.5};
    }
    Extent e{w.bounds.min, w.bounds.max};
    switch (index) {
    case kWallLeft:
        e.hi.x = w.bounds.min.x;
        break;
    case kWallRight:
        e.lo.x = w.bounds.max.x;
        break;
    case kWallBottom:
        e.hi.y = w.bounds.min.y;
        break;
    default:
        e.lo.y = w.bounds.max.y;
        break; // kWallTop
    }
    return e;
}

// The middle of the touching faces: along the contact's axis the first body's face toward the
// other (record.firstBelow; a wall is on its own side), across it the middle of the span the
// two share.
Vec2 contactPoint(const World& w, const CollisionRecord& r) {
    const Extent a = extentOf(w, r.block), b = extentOf(w, r.other);
    const int n = r.axis, t = 1 - r.axis;
    Vec2 p;
    if (r.other >= 0)
        p[n] = r.firstBelow ? a.hi[n] : a.lo[n];
    else // a wall: the block's face toward it
        p[n] = r.other == kWallLeft || r.other == kWallBottom ? a.lo[n] : a.hi[n];
    const double lo = std::max(a.lo[t], b.lo[t]), hi = std::min(a.hi[t], b.hi[t]);
    p[t] = lo <= hi ? 0.5 * (lo + hi) : 0.5 * (a.lo[t] + a.hi[t]);
    return p;
}

// A body's velocity along an axis now (a wall's is 0).
double velocityAlong(const World& w, int index, int axis) {
    return index >= 0 ? w.blocks[static_cast<std::size_t>(index)].velocity[axis] : 0.0;
}

} // namespace

void drawContactsOverlay(App& app) {
    const World& w = app.sim.world();
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const float s = app.view.uiScale;
    const ImU32 hit = uiMarkColor(Mark::PoiContact), push = uiMarkColor(Mark::Force);
    const float radius = 5.0f * s, arrow = 22.0f * s, head = 6.0f * s;
    for (const CollisionRecord& r : app.sim.run.lastLog) {
        if (r.block < 0 || r.block >= static_cast<int>(w.blocks.size())) continue;
        if (r.other >= static_cast<int>(w.blocks.size()) || r.other < kWallTop) continue;
        const ImVec2 at = toScreen(app, contactPoint(w, r));
        if (r.rest)
            dl->AddCircle(at, radius, hit, 12, 2.0f * s);
        else
            dl->AddCircleFilled(at, radius, hit, 12);
        if (r.mu <= 0.0 || r.dvt == 0.0) continue;
        // Friction acts against the first body's sliding along the face relative to the other
        // (record.dvt is its size, not its sign): an arrow against that sliding while it goes
        // on, a bar along the face once the two move together (static friction holding).
        const int t = 1 - r.axis;
        const double rel = velocityAlong(w, r.block, t) - velocityAlong(w, r.other, t);
        const ImVec2 along = t == 0 ? ImVec2(1.0f, 0.0f) : ImVec2(0.0f, -1.0f); // screen y down
        if (std::abs(rel) <= w.settings.restSpeed) {
            const ImVec2 half(along.x * arrow * 0.5f, along.y * arrow * 0.5f);
            dl->AddLine(ImVec2(at.x - half.x, at.y - half.y), ImVec2(at.x + half.x, at.y + half.y),
                        push, 3.0f * s);
            continue;
        }
        const float sign = rel > 0.0 ? -1.0f : 1.0f;
        const ImVec2 dir(along.x * sign, along.y * sign);
        const ImVec2 tip(at.x + dir.x * arrow, at.y + dir.y * arrow);
        dl->AddLine(at, tip, push, 2.5f * s);
        const ImVec2 side(-dir.y * head * 0.6f, dir.x * head * 0.6f);
        dl->AddTriangleFilled(
            tip, ImVec2(tip.x - dir.x * head + side.x, tip.y - dir.y * head + side.y),
            ImVec2(tip.x - dir.x * head - side.x, tip.y - dir.y * head - side.y), push);
    }
}
