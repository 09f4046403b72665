// The values at arrows' heads (arrow_values.h).
#include "arrow_values.h"

#include "inspector_format.h"
#include "printed_formula.h"
#include "scene_geometry.h"
#include "text_format.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace {

// Arrows whose value is written beside them when they are not drawn to scale, at most.
constexpr int kMaxArrowValueLabels = 20;

ImU32 packed(const Color& c) {
    return c.packed();
}

const SceneTheme& theme() {
    return sceneTheme(uiLightTheme());
}

// A value written at the head of an arrow (from `base` to `tip`, m) cut at the view's edge or the
// arena's wall: over the head (beside a vertical one), kept inside the view, in a free row.
void drawValueAtTip(const App& app, ImDrawList* dl, Taken& placed, Vec2 base, Vec2 tip,
                    const std::string& text, ImU32 color, const BlockStrips& blocks) {
    const ImVec2 ts = ImGui::CalcTextSize(text.c_str());
    const ScreenRect& vp = app.view.camera.viewport();
    const Vec2 at = app.view.camera.worldToScreen(tip);
    // Beside the shaft of a vertical arrow (on the side with room), centred over a sideways one.
    const Vec2 from = app.view.camera.worldToScreen(base);
    const bool vertical = std::abs(at.y - from.y) > std::abs(at.x - from.x);
    float x = static_cast<float>(at.x) - ts.x * 0.5f;
    if (vertical) {
        x = static_cast<float>(at.x) + 8.0f;
        if (x + ts.x > vp.x + vp.width) x = static_cast<float>(at.x) - 8.0f - ts.x;
    }
    x = std::clamp(x, static_cast<float>(vp.x), static_cast<float>(vp.x + vp.width) - ts.x);
    const ImVec2 spot =
        freeRow(placed, vp, x,
                std::clamp(static_cast<float>(at.y) - ts.y - 6.0f, static_cast<float>(vp.y),
                           static_cast<float>(vp.y + vp.height) - ts.y),
                ts, &blocks);
    placed.texts.push_back({spot.x, spot.y, ts.x, ts.y});
    shadowText(dl, spot, color, text.c_str(), packed(theme().textShadow));
}

// Block `i`'s velocity and mass as the collision inspector prints them, when they are what the
// block has now: the inspector is shown, the collision it shows is the block's and left it with
// the velocity it has now (along that axis, none across), seen in the world's frame. Otherwise
// empty texts.
struct InspectedBlock {
    std::string massText, velocityText; // as printed, the velocity with its sign
};

InspectedBlock inspectedBlock(const App& app, std::size_t i) {
    const auto& recent = app.sim.telemetry.recent;
    if (!app.view.show.inspector || recent.empty() || app.view.frame != ViewFrame::World) return {};
    const int count = static_cast<int>(recent.size());
    const int picked = app.ui.inspectorPicked < count ? app.ui.inspectorPicked : 0;
    const CollisionRecord& r = recent[static_cast<std::size_t>(count - 1 - picked)];
    const int index = static_cast<int>(i);
    if (index != r.block && index != r.other) return {};
    const Block& b = app.sim.world().blocks[i];
    const double along = r.axis == 0 ? b.velocity.x : b.velocity.y;
    const double across = r.axis == 0 ? b.velocity.y : b.velocity.x;
    const double after = index == r.block ? r.v1After : r.v2After;
    if (along != after || across != 0.0) return {};
    const auto name = [&app](int k) {
        return k < 0 ? std::string(wallName(k)) : app.sim.blockDisplayName(k);
    };
    const CollisionFormula f = collisionFormula(r, name(r.block), name(r.other));
    return index == r.block ? InspectedBlock{f.m1Text, f.v1AfterText}
                            : InspectedBlock{f.m2Text, f.v2AfterText};
}

// The momentum of block `i` as the inspector's numbers give it (inspectedBlock), "" when they do
// not: m·v' with m and v' as the inspector prints them (productAsPrinted), so that the arrow and
// the inspector never write different digits for one quantity (the giant of high_mass_ratio:
// 1000000·0.9999999175 = 999999.9175, where formatNumber alone wrote 999999.917).
std::string momentumAsInspected(const App& app, std::size_t i) {
    const InspectedBlock inspected = inspectedBlock(app, i);
    if (inspected.velocityText.empty()) return "";
    return productAsPrinted(inspected.massText, inspected.velocityText);
}

// True when block `i`'s momentum arrow carries its value (drawMomentumValues): too long to draw
// to scale.
bool momentumValueShown(const App& app, std::size_t i) {
    const Block& b = app.sim.world().blocks[i];
    if (!app.view.show.vectors || !b.isDynamic()) return false;
    const Vec2 p = (b.velocity - frameVelocity(app.sim.world(), app.view.frame)) * b.mass;
    return !arrowOnScreen(app.view.camera, b.position, p * kMomentumArrowScale,
                          &app.sim.world().bounds)
                .toScale;
}

// A block's speed as its velocity arrow writes it. Where its momentum's value is written too,
// the two are one quantity, p = m·|v|: the speed gets the digits with which m·|v| as printed
// gives |p| as printed (equationWithFewestDigits' rule; bouncing_squares' green block, 4 kg:
// 8.36637 m/s and 33.465 kg·m/s, where 8.366 gave 33.464), or the inspector's own digits where
// the momentum is written from them (momentumAsInspected).
std::string speedText(const App& app, std::size_t i, double speed) {
    if (!momentumValueShown(app, i)) return formatNumber(speed);
    const InspectedBlock inspected = inspectedBlock(app, i);
    if (!productAsPrinted(inspected.massText, inspected.velocityText).empty()) {
        const std::string& v = inspected.velocityText; // the momentum is written from it
        return v[0] == '-' ? v.substr(1) : v;
    }
    const Block& b = app.sim.world().blocks[i];
    const std::string momentum = formatNumber(b.mass * speed);
    int extra = 0;
    while (extra < kMostExtraDigits &&
           !givesResult(printed(b.mass, 0) * printed(speed, extra), momentum))
        ++extra;
    return formatNumberWithDigits(speed, extra);
}

} // namespace

// The momentum arrows too long to draw to scale carry their value at their head (p = m·w in
// the view's frame), in the momentum arrows' colour; with the inspector's digits where it shows
// the block's last collision (momentumAsInspected).
void drawMomentumValues(const App& app, ImDrawList* dl, Taken& placed,
                        std::optional<BlockStrips>& blocks) {
    if (!app.view.show.vectors) return;
    const Vec2 u = frameVelocity(app.sim.world(), app.view.frame);
    const ArrowsOnScreen arrows(app.view.camera, &app.sim.world().bounds);
    int written = 0;
    for (std::size_t i = 0; i < app.sim.world().blocks.size(); ++i) {
        const Block& b = app.sim.world().blocks[i];
        if (!b.isDynamic() || written >= kMaxArrowValueLabels) continue;
        const Vec2 p = (b.velocity - u) * b.mass;
        const ArrowOnScreen a = arrows(b.position, p * kMomentumArrowScale);
        if (a.toScale) continue;
        const std::string inspected = momentumAsInspected(app, i);
        if (!blocks) blocks = blockStrips(placed, app.view.camera.viewport());
        drawValueAtTip(
            app, dl, placed, b.position, a.tip,
            (inspected.empty() ? formatNumber(b.mass * length(b.velocity - u)) : inspected) +
                " kg·m/s",
            packed(theme().momentum.withAlpha(1.0f)), *blocks);
        ++written;
    }
}

// Arrows too long to draw to scale (compressed and cut at the view's edge) carry their value; in
// the centre-of-mass frame every arrow does (w1 = 4 m/s: the lecture's numbers), in a scene of
// few blocks.
void drawArrowValues(const App& app, ImDrawList* dl, Taken& placed,
                     std::optional<BlockStrips>& blocks) {
    if (!app.view.show.vectors) return;
    const bool relative = app.view.frame != ViewFrame::World;
    const Vec2 u = frameVelocity(app.sim.world(), app.view.frame);
    const bool labelAll =
        relative && app.sim.world().blocks.size() <= static_cast<std::size_t>(kCrowdedScene);
    const ArrowsOnScreen arrows(app.view.camera, &app.sim.world().bounds);
    int written = 0;
    for (std::size_t i = 0; i < app.sim.world().blocks.size(); ++i) {
        const Block& b = app.sim.world().blocks[i];
        if (b.kind == BodyKind::Static || written >= kMaxArrowValueLabels) continue;
        const Vec2 w = b.velocity - u;
        const ArrowOnScreen a = arrows(b.position, w * kVelocityArrowScale);
        if (a.toScale && !labelAll) continue;
        const std::string text =
            relative ? frameVelocityLabel(i < app.sim.labels.size() ? app.sim.labels[i].name : "",
                                          w, app.view.frame)
                     : speedText(app, i, length(w)) + " m/s";
        const ImVec2 ts = ImGui::CalcTextSize(text.c_str());
        const ScreenRect& vp = app.view.camera.viewport();
        // Over the arrow's head; every arrow's value (labelAll): under its block (the name is
        // over it), moved down a line at a time until it overlaps no value written before.
        Vec2 at = app.view.camera.worldToScreen(a.tip);
        at.y -= ts.y + 6.0;
        if (labelAll) {
            at = app.view.camera.worldToScreen(b.position - Vec2{0.0, b.size.y * 0.5});
            at.y += 3.0;
        }
        const float x = std::clamp(static_cast<float>(at.x) - ts.x * 0.5f, static_cast<float>(vp.x),
                                   static_cast<float>(vp.x + vp.width) - ts.x);
        if (!blocks) blocks = blockStrips(placed, vp);
        const ImVec2 spot = freeRow(placed, vp, x, static_cast<float>(at.y), ts, &*blocks);
        placed.texts.push_back({spot.x, spot.y, ts.x, ts.y});
        shadowText(dl, spot, packed(theme().velocity), text.c_str(), packed(theme().textShadow));
        ++written;
    }
}

// Force arrows carry their value, "F = 2 N" (or the vector when it is not along an axis), at the
// head: the arrow's length is to scale only up to the knee.
void drawForceValues(const App& app, const SceneView& view, ImDrawList* dl, Taken& placed,
                     std::optional<BlockStrips>& blocks) {
    int written = 0;
    for (std::size_t i = 0; i < app.sim.world().blocks.size() && written < kMaxArrowValueLabels;
         ++i) {
        const Vec2 f = shownForce(view, i);
        if (f == Vec2{}) continue;
        const Block& b = app.sim.world().blocks[i];
        const ArrowOnScreen a = arrowOnScreen(app.view.camera, b.position, f * kForceArrowScale,
                                              &app.sim.world().bounds);
        char text[80];
        if (f.x == 0.0 || f.y == 0.0) {
            std::snprintf(text, sizeof text, "F = %s N", formatNumber(length(f)).c_str());
        } else {
            std::snprintf(text, sizeof text, "F = (%s, %s) N", formatNumber(f.x).c_str(),
                          formatNumber(f.y).c_str());
        }
        const Vec2 tip = app.view.camera.worldToScreen(a.tip);
        const ImVec2 ts = ImGui::CalcTextSize(text);
        const ScreenRect& vp = app.view.camera.viewport();
        // Past the head, along the arrow: beside it for a mostly sideways force, above or
        // below it for a mostly vertical one (kept in the view).
        const float gap = 6.0f, tx = static_cast<float>(tip.x), ty = static_cast<float>(tip.y);
        float x = tx - ts.x * 0.5f, y = f.y > 0.0 ? ty - ts.y - gap : ty + gap;
        if (std::abs(f.x) >= std::abs(f.y)) {
            x = f.x > 0.0 ? tx + gap : tx - gap - ts.x;
            y = ty - ts.y * 0.5f;
        }
        x = std::clamp(x, static_cast<float>(vp.x), static_cast<float>(vp.x + vp.width) - ts.x);
        if (!blocks) blocks = blockStrips(placed, vp);
        const ImVec2 at = freeSpot(placed, vp, x, y, y, ts, ts.y, &*blocks); // clear of the texts
        placed.texts.push_back({at.x, at.y, ts.x, ts.y});
        shadowText(dl, at, sceneTheme(app.view.lightTheme).force.packed(), text,
                   packed(theme().textShadow));
        ++written;
    }
}
