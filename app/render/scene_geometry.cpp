#include "scene_geometry.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kWallThicknessPx = 10.0;
constexpr double kArrowWidthPx = 2.5; // the fling arrow's shaft (triangles)
constexpr double kArrowHeadPx = 11.0;
constexpr double kForceShaftPx = 5.0; // force arrows (triangles)
constexpr double kGridMinPx = 12.0;

} // namespace

double displayedArrowPx(double lengthPx, double kneePx) {
    if (!(lengthPx > kneePx) || !(kneePx > 0.0)) return std::max(0.0, lengthPx);
    return std::min(2.0 * kneePx, kneePx * (1.0 + std::log(lengthPx / kneePx)));
}

ArrowOnScreen arrowOnScreen(const Camera& camera, Vec2 from, Vec2 vector, const Bounds* arena) {
    return ArrowsOnScreen(camera, arena)(from, vector);
}

ArrowsOnScreen::ArrowsOnScreen(const Camera& camera, const Bounds* arena) : camera_(camera) {
    const ScreenRect& vp = camera.viewport();
    knee_ = kArrowKneeShare * std::min(vp.width, vp.height);
    // The head stays inside the viewport and the arena.
    limits_[0][0] = vp.x, limits_[0][1] = vp.x + vp.width;
    limits_[1][0] = vp.y, limits_[1][1] = vp.y + vp.height;
    if (arena) {
        const Vec2 a = camera.worldToScreen(arena->min), b = camera.worldToScreen(arena->max);
        const double box[2][2] = {{std::min(a.x, b.x), std::max(a.x, b.x)},
                                  {std::min(a.y, b.y), std::max(a.y, b.y)}};
        for (int k = 0; k < 2; ++k) {
            limits_[k][0] = std::max(limits_[k][0], box[k][0]);
            limits_[k][1] = std::min(limits_[k][1], box[k][1]);
        }
    }
}

ArrowOnScreen ArrowsOnScreen::operator()(Vec2 from, Vec2 vector) const {
    ArrowOnScreen a;
    const double size = length(vector);
    const double lengthPx = size * camera_.pixelsPerMetre();
    if (!(lengthPx > 0.0) || !std::isfinite(lengthPx)) {
        a.tip = from;
        return a;
    }
    double shown = displayedArrowPx(lengthPx, knee_);
    // Cut where the arrow leaves the viewport or the arena.
    const Vec2 s = camera_.worldToScreen(from);
    const Vec2 dir{vector.x / size, -vector.y / size}; // screen, y down
    const double start[2] = {s.x, s.y}, d[2] = {dir.x, dir.y};
    for (int k = 0; k < 2; ++k) {
        if (start[k] < limits_[k][0] || start[k] > limits_[k][1]) continue; // from off screen
        if (d[k] > 1e-12) shown = std::min(shown, (limits_[k][1] - 2.0 - start[k]) / d[k]);
        if (d[k] < -1e-12) shown = std::min(shown, (limits_[k][0] + 2.0 - start[k]) / d[k]);
    }
    shown = std::max(0.0, shown);
    a.toScale = shown >= lengthPx - 1e-9;
    a.tip = from + vector * (shown / lengthPx);
    return a;
}

Vec2 shownForce(const SceneView& view, std::size_t index) {
    if (!view.world || index >= view.world->blocks.size()) return {};
    const Block& b = view.world->blocks[index];
    if (!b.isDynamic()) return {};
    const bool thrusted = static_cast<int>(index) == view.thrustBlock;
    if (!view.vectors && !thrusted) return {};
    return thrusted ? b.force + view.thrust : b.force;
}

void SceneGeometry::build(const SceneView& view, double maxPointPx) {
    under.clear();
    momenta.clear();
    over.clear();
    addGrid(view);
    if (view.trails) addTrails(view, *view.trails);
    if (view.vectors || view.thrustBlock >= 0) addArrows(view);
    if (view.flingActive) {
        const double px = view.camera->pixelsToMetres(1.0);
        over.arrow(view.flingFrom, view.flingTo, kArrowWidthPx * 1.6 * px, kArrowHeadPx * 1.5 * px,
                   scene_colors::kFling);
    }
    addBlocks(view, maxPointPx);
}

// The metre grid, limited to what is visible inside the bounds.
void SceneGeometry::addGrid(const SceneView& view) {
    const World& world = *view.world;
    const Camera& cam = *view.camera;
    const double px = cam.pixelsToMetres(1.0);
    const ScreenRect& vp = cam.viewport();
    const Vec2 a = cam.screenToWorld({vp.x, vp.y + vp.height});
    const Vec2 b = cam.screenToWorld({vp.x + vp.width, vp.y});
    const Vec2 lo{std::max(a.x, world.bounds.min.x), std::max(a.y, world.bounds.min.y)};
    const Vec2 hi{std::min(b.x, world.bounds.max.x), std::min(b.y, world.bounds.max.y)};
    if (!(lo.x < hi.x && lo.y < hi.y)) return;
    const double step = gridSpacing(cam.pixelsPerMetre(), kGridMinPx);
    const double major = step * 5.0;
    const double x0 = world.bounds.min.x + std::ceil((lo.x - world.bounds.min.x) / step) * step;
    for (double x = x0; x <= hi.x; x += step) {
        const double m = std::fmod(std::abs(x - world.bounds.min.x) + 1e-9, major);
        const bool isMajor = m < 1e-6;
        under.rect({x - px * 0.5, lo.y}, {x + px * 0.5, hi.y},
                   isMajor ? view.theme->gridMajor : view.theme->gridMinor);
    }
    const double y0 = world.bounds.min.y + std::ceil((lo.y - world.bounds.min.y) / step) * step;
    for (double y = y0; y <= hi.y; y += step) {
        const double m = std::fmod(std::abs(y - world.bounds.min.y) + 1e-9, major);
        const bool isMajor = m < 1e-6;
        under.rect({lo.x, y - px * 0.5}, {hi.x, y + px * 0.5},
                   isMajor ? view.theme->gridMajor : view.theme->gridMinor);
    }
}

// Trails, fading with age, as GL lines. A software rasteriser pays for every pixel of their
// length, so at most kTrailPixelBudget pixels of trail are drawn: all trails are cut at the same
// age (a crowded scene shows short tails), and with many blocks only every k-th stored point is
// used, to stay within kTrailSegmentBudget segments. With every point used, a trail passes
// through each point of impact it kept (Trails::impact).
void SceneGeometry::addTrails(const SceneView& view, const Trails& trails) {
    const World& world = *view.world;
    const double px = view.camera->pixelsToMetres(1.0);
    const int oldest = trails.ageWithinLength(world, kTrailPixelBudget * px);
    if (oldest < 1) return;
    std::size_t moving = 0;
    for (const Block& bl : world.blocks) moving += bl.kind != BodyKind::Static;
    const long long wanted = static_cast<long long>(moving) * oldest;
    const int stride = static_cast<int>(
        std::max<long long>(1, (wanted + kTrailSegmentBudget - 1) / kTrailSegmentBudget));
    const auto fade = [oldest](int age) {
        return 0.75f * (1.0f - static_cast<float>(age) / static_cast<float>(oldest + 1));
    };
    // Every block's trail goes through the same ages (0, stride, 2·stride, ..., oldest): their
    // slots in the ring and their fades once for all blocks (a crowded scene: thousands of
    // segments a frame).
    trailSteps_.clear();
    for (int prevAge = 0; prevAge < oldest;) {
        const int age = std::min(prevAge + stride, oldest);
        trailSteps_.push_back({trails.slotOfAge(age), stride == 1 && prevAge + 1 < trails.length(),
                               fade(age), 0.5f * (fade(prevAge) + fade(age))});
        prevAge = age;
    }
    const int newest = trails.slotOfAge(0);
    const float newestAlpha = fade(0);
    for (std::size_t i = 0; i < trails.blockCount(); ++i) {
        if (world.blocks[i].kind == BodyKind::Static) continue;
        const Color c = i < view.blockColors.size() ? view.blockColors[i] : Color{};
        Vec2 prev = trails.pointIn(i, newest);
        float prevAlpha = newestAlpha;
        int prevSlot = newest;
        for (const TrailStep& s : trailSteps_) {
            const Vec2 p = trails.pointIn(i, s.slot);
            Vec2 hit;
            if (s.throughImpact && trails.impactIn(i, prevSlot, hit)) {
                // Through the point of impact: the path that happened (trails.h).
                under.segment(prev, hit, c.withAlpha(prevAlpha), c.withAlpha(s.mid));
                under.segment(hit, p, c.withAlpha(s.mid), c.withAlpha(s.alpha));
            } else {
                under.segment(prev, p, c.withAlpha(prevAlpha), c.withAlpha(s.alpha));
            }
            prev = p;
            prevAlpha = s.alpha;
            prevSlot = s.slot;
        }
    }
}

// Momentum arrows (wide, translucent, under) and velocity arrows from the centres of moving
// blocks: p = m·v points the same way as v, so the two share a line. Both as seen in the view's
// frame: w = v - u in the centre of mass's.
void SceneGeometry::addArrows(const SceneView& view) {
    const double px = view.camera->pixelsToMetres(1.0);
    const ArrowsOnScreen arrows(*view.camera, &view.world->bounds); // ending at the arena's walls
    // Forces: wide arrows under the velocity arrows (a thrust along the motion shares their line).
    for (std::size_t i = 0; i < view.world->blocks.size(); ++i) {
        const Vec2 f = shownForce(view, i);
        if (f == Vec2{}) continue;
        const Vec2 from = view.world->blocks[i].position;
        const Vec2 tip = arrows(from, f * kForceArrowScale).tip;
        over.arrow(from, tip, kForceShaftPx * px, kArrowHeadPx * 1.3 * px, view.theme->force);
    }
    if (!view.vectors) return;
    std::size_t dynamic = 0;
    for (const Block& bl : view.world->blocks) dynamic += bl.isDynamic();
    const bool heads = dynamic <= kMomentumHeadsUpTo;
    for (const Block& bl : view.world->blocks) {
        if (!bl.isDynamic()) continue;
        const Vec2 tip = arrows(bl.position, (bl.velocity - view.frameVelocity) *
                                                 (bl.mass * kMomentumArrowScale))
                             .tip;
        if (heads)
            momenta.lineArrow(bl.position, tip, kArrowHeadPx * 1.3 * px, view.theme->momentum);
        else
            momenta.segment(bl.position, tip, view.theme->momentum);
    }
    for (const Block& bl : view.world->blocks) {
        if (bl.kind == BodyKind::Static) continue;
        const Vec2 tip =
            arrows(bl.position, (bl.velocity - view.frameVelocity) * kVelocityArrowScale).tip;
        over.lineArrow(bl.position, tip, kArrowHeadPx * px, view.theme->velocity);
    }
}

const SceneGeometry::OutlineOf& SceneGeometry::outlineOf(const Color& fill, const Color& arena) {
    const auto same = [](const Color& a, const Color& b) {
        return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
    };
    for (const OutlineOf& o : outlines_)
        if (same(o.fill, fill) && same(o.arena, arena)) return o;
    if (outlines_.size() >= 64) outlines_.clear(); // a scene of many colours: a fresh table
    outlines_.push_back(
        {fill, arena, outlineFor(fill, arena), contrastRatio(fill, arena) < kMinBlockContrast});
    return outlines_.back();
}

// The walls, the blocks and the ghosts, each as a point sprite or a quad.
void SceneGeometry::addBlocks(const SceneView& view, double maxPointPx) {
    const World& world = *view.world;
    const double px = view.camera->pixelsToMetres(1.0);
    for (auto& shapes : blocks) {
        for (std::vector<BlockInstance>& list : shapes) list.clear();
    }
    const Camera& cam = *view.camera;
    const auto add = [&](BlockStyle style, const BlockInstance& b) {
        const ScreenRect onScreen{0.0, 0.0, view.displayWidth, view.displayHeight};
        const bool point = drawsAsPointSprite(
            2.0 * b.rect[2] * cam.pixelsPerMetre(), 2.0 * b.rect[3] * cam.pixelsPerMetre(),
            cam.worldToScreen({b.rect[0], b.rect[1]}), onScreen, maxPointPx);
        blocks[style][point ? kPoint : kQuad].push_back(b);
    };

    // The four walls, just outside the bounds, hatched like every body of infinite mass.
    const double t = kWallThicknessPx * px;
    const Vec2 mn = world.bounds.min, mx = world.bounds.max;
    const Color wall = view.theme->wall;
    const Vec2 wallRects[4][2] = {{{mn.x - t, mn.y - t}, {mn.x, mx.y + t}},
                                  {{mx.x, mn.y - t}, {mx.x + t, mx.y + t}},
                                  {{mn.x, mn.y - t}, {mx.x, mn.y}},
                                  {{mn.x, mx.y}, {mx.x, mx.y + t}}};
    for (const auto& r : wallRects) {
        const Vec2 c = (r[0] + r[1]) * 0.5, h = (r[1] - r[0]) * 0.5;
        blocks[kPatterned][kQuad].push_back({{float(c.x), float(c.y), float(h.x), float(h.y)},
                                             {wall.r, wall.g, wall.b, wall.a},
                                             {wall.r, wall.g, wall.b, wall.a},
                                             {0.0f, 1.0f}});
    }

    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        const Color fill = i < view.blockColors.size() ? view.blockColors[i] : Color{};
        const bool selected = static_cast<int>(i) == view.selected;
        // Outlined so every block stands out from the arena, whatever its colour.
        const OutlineOf& o = outlineOf(fill, view.theme->arena);
        const Color outline = selected ? scene_colors::kSelection : o.outline;
        const bool faint = !selected && o.faint;
        const float pattern = b.kind == BodyKind::Static      ? 1.0f
                              : b.kind == BodyKind::Kinematic ? 2.0f
                                                              : 0.0f;
        add(pattern > 0.0f ? kPatterned : kPlain, {{float(b.position.x), float(b.position.y),
                                                    float(b.size.x * 0.5), float(b.size.y * 0.5)},
                                                   {fill.r, fill.g, fill.b, fill.a},
                                                   {outline.r, outline.g, outline.b, outline.a},
                                                   {selected ? 3.0f
                                                    : faint  ? 2.5f
                                                             : 1.5f,
                                                    pattern}});
    }

    // Ghosts: outlines only (a transparent fill), in each ghost world's colour.
    for (const SceneView::Ghosts& g : view.ghosts) {
        if (!g.world) continue;
        const Color c = g.color;
        for (const Block& b : g.world->blocks) {
            if (b.kind == BodyKind::Static) continue;
            add(kOutlineOnly, {{float(b.position.x), float(b.position.y), float(b.size.x * 0.5),
                                float(b.size.y * 0.5)},
                               {c.r, c.g, c.b, 0.0f},
                               {c.r, c.g, c.b, 0.95f},
                               {2.0f, 0.0f}});
        }
    }
}

PixelBox drawnBox(const SceneGeometry& geometry, const ClipTransform& t, int width, int height,
                  double lineWidthPx, double marginPx) {
    // In pixels from the framebuffer's left and top: clip = world * scale + offset.
    const double sx = 0.5 * width * t.scaleX, ox = 0.5 * width * (t.offsetX + 1.0);
    const double sy = -0.5 * height * t.scaleY, oy = 0.5 * height * (1.0 - t.offsetY);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    const auto add = [&](double wx, double wy, double reachX, double reachY) {
        const double px = wx * sx + ox, py = wy * sy + oy;
        x0 = std::min(x0, px - reachX);
        x1 = std::max(x1, px + reachX);
        y0 = std::min(y0, py - reachY);
        y1 = std::max(y1, py + reachY);
    };
    const double halfLine = 0.5 * lineWidthPx;
    for (const ShapeBatch* batch : {&geometry.under, &geometry.momenta, &geometry.over}) {
        for (const ShapeVertex& v : batch->vertices()) add(v.x, v.y, 0.0, 0.0);
        for (const ShapeVertex& v : batch->segmentVertices()) add(v.x, v.y, halfLine, halfLine);
    }
    const double pxX = std::abs(sx), pxY = std::abs(sy); // pixels per metre
    for (const auto& shapes : geometry.blocks) {
        for (const BlockInstance& b : shapes[kQuad])
            add(b.rect[0], b.rect[1], b.rect[2] * pxX, b.rect[3] * pxY);
        for (const BlockInstance& b : shapes[kPoint]) {
            // A point sprite is a square of the larger side plus 2 px (block.vert).
            const double reach = std::max(b.rect[2] * pxX, b.rect[3] * pxY) + 1.0;
            add(b.rect[0], b.rect[1], reach, reach);
        }
    }
    if (!(x0 <= x1) || !std::isfinite(x0 + x1 + y0 + y1)) {
        if (x0 <= x1) return {0, 0, width, height}; // a coordinate beyond reckoning: everywhere
        return {};
    }
    PixelBox box;
    box.x0 = static_cast<int>(std::clamp(std::floor(x0 - marginPx), 0.0, double(width)));
    box.x1 = static_cast<int>(std::clamp(std::ceil(x1 + marginPx), 0.0, double(width)));
    box.y0 = static_cast<int>(std::clamp(std::floor(y0 - marginPx), 0.0, double(height)));
    box.y1 = static_cast<int>(std::clamp(std::ceil(y1 + marginPx), 0.0, double(height)));
    return box;
}
