// The magnifier's inset (magnifier.h).
#include "magnifier.h"

#include "dock_layout.h"
#include "palette.h"
#include "placement.h"
#include "screen_text.h"
#include "text_format.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// The factors a magnifier states, round so that a class reads them at a glance.
constexpr double kFactors[] = {2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40, 50};
constexpr std::size_t kMaxBlocks = 50; // a lesson's world; a gas names no block
constexpr std::size_t kMaxInsets = 4;
constexpr double kShare = 0.45; // of the scene's width and height, an inset at most

// `name` is a word of `text` (not part of a longer one: "m1" is not in "m12").

// Everything the step's caption bar can say, as written.
std::string stepWords(const LessonStep& step) {
    std::string words =
        step.title + "\n" + step.caption + "\n" + step.question + "\n" + step.answer;
    for (const LessonChoice& c : step.choices) words += "\n" + c.text.source;
    return words;
}

struct Group {
    std::vector<std::size_t> blocks;
    Bounds box; // m, the blocks' union
    double factor = 1.0;
};

double shortSide(const Block& b) {
    return std::min(b.size.x, b.size.y);
}

Bounds boxOf(const Block& b) {
    return {b.position - b.size * 0.5, b.position + b.size * 0.5};
}

Bounds joined(const Bounds& a, const Bounds& b) {
    return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y)},
            {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y)}};
}

// The least round factor that draws `side` px at `target` px or more (the largest there is).
double factorFor(double side, double target) {
    for (const double f : kFactors)
        if (side * f >= target) return f;
    return kFactors[std::size(kFactors) - 1];
}

// The inset's size (px) for `g` at `ppm` px/m in the scene: its box magnified, with `pad` around.
ImVec2 insetSize(const Group& g, double ppm, double pad, const ScreenRect& vp) {
    const double s = ppm * g.factor;
    return ImVec2(static_cast<float>(
                      std::min((g.box.max.x - g.box.min.x) * s + 2.0 * pad, kShare * vp.width)),
                  static_cast<float>(
                      std::min((g.box.max.y - g.box.min.y) * s + 2.0 * pad, kShare * vp.height)));
}

// The top-left of the inset: the spot along the scene's edges and corners covering the least
// of what is taken (blocks, marks, texts) and of the axis numbers' bands (under the world and
// left of it, drawn after it), top right first.
ImVec2 insetSpot(const App& app, const Taken& placed, const ScreenRect& vp, ImVec2 size) {
    Taken taken = placed;
    const double font = ImGui::GetFontSize();
    const ScreenRect w = worldRectOnScreen(app.view.camera, app.sim.world().bounds);
    taken.texts.push_back({w.x - 2.0 * font, w.y + w.height, w.width + 4.0 * font, 1.8 * font});
    taken.texts.push_back({w.x - 3.0 * font, w.y - font, 3.0 * font, w.height + 2.0 * font});
    const float m = 6.0f;
    const float left = static_cast<float>(vp.x) + m;
    const float right = static_cast<float>(vp.x + vp.width) - size.x - m;
    const float top = static_cast<float>(vp.y) + m;
    const float bottom = static_cast<float>(vp.y + vp.height) - size.y - m;
    const float midX = 0.5f * (left + right), midY = 0.5f * (top + bottom);
    const ImVec2 tries[] = {{right, top}, {right, bottom}, {left, top},   {left, bottom},
                            {midX, top},  {midX, bottom},  {right, midY}, {left, midY}};
    ImVec2 best = tries[0];
    double least = INFINITY;
    for (const ImVec2& at : tries) {
        const double covered = coveredAt(taken, vp, at.x, at.y, size, 0.0f);
        if (covered < least) {
            least = covered;
            best = at;
        }
    }
    return best;
}

void drawInset(App& app, ImDrawList* dl, Taken& placed, const Group& g, double target) {
    const Camera& cam = app.view.camera;
    const ScreenRect& vp = cam.viewport();
    const double ppm = cam.pixelsPerMetre();
    const double pad = 0.5 * target;
    const ImVec2 size = insetSize(g, ppm, pad, vp);
    if (size.x < 2.0f * target || size.y < 2.0f * target) return; // no room for one
    const ImVec2 at = insetSpot(app, placed, vp, size);
    const ImVec2 end(at.x + size.x, at.y + size.y);
    const double s = ppm * g.factor; // px/m in the inset
    const Vec2 centre = (g.box.min + g.box.max) * 0.5;
    const ImVec2 middle(at.x + size.x * 0.5f, at.y + size.y * 0.5f);
    const auto toInset = [&](Vec2 p) {
        return ImVec2(middle.x + static_cast<float>((p.x - centre.x) * s),
                      middle.y - static_cast<float>((p.y - centre.y) * s));
    };
    const SceneTheme& theme = sceneTheme(uiLightTheme());
    const World& world = app.sim.world();
    // The world it shows: walls outside the bounds, the arena inside, every block in it.
    dl->PushClipRect(at, end, true);
    dl->AddRectFilled(at, end, theme.wall.packed());
    const ImVec2 lo = toInset(world.bounds.min), hi = toInset(world.bounds.max);
    dl->AddRectFilled(ImVec2(lo.x, hi.y), ImVec2(hi.x, lo.y), theme.arena.packed());
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Bounds b = boxOf(world.blocks[i]);
        const ImVec2 a = toInset({b.min.x, b.max.y}), z = toInset({b.max.x, b.min.y});
        if (z.x < at.x || a.x > end.x || z.y < at.y || a.y > end.y) continue;
        const Color fill = app.sim.blockDisplayColor(static_cast<int>(i));
        dl->AddRectFilled(a, z, fill.packed());
        dl->AddRect(a, z, outlineFor(fill, theme.arena).packed());
    }
    {
        const TextRole role(dl, "magnifier");
        for (const std::size_t i : g.blocks) {
            const Bounds b = boxOf(world.blocks[i]);
            const ImVec2 a = toInset({b.min.x, b.max.y}), z = toInset({b.max.x, b.min.y});
            // As drawn: its part in the inset.
            const ImVec2 a2(std::max(a.x, at.x), std::max(a.y, at.y));
            const ImVec2 z2(std::min(z.x, end.x), std::min(z.y, end.y));
            if (z2.x <= a2.x || z2.y <= a2.y) continue;
            const std::string name = app.sim.blockDisplayName(static_cast<int>(i));
            app.view.shownMagnified.push_back({name, spanning(a2.x, a2.y, z2.x, z2.y)});
            const ImVec2 ts = ImGui::CalcTextSize(name.c_str());
            if (ts.x > z2.x - a2.x - 6.0f || ts.y > z2.y - a2.y - 4.0f) continue;
            const ImVec2 p(0.5f * (a2.x + z2.x - ts.x), 0.5f * (a2.y + z2.y - ts.y));
            dl->AddText(ImVec2(p.x + 1.0f, p.y + 1.0f), IM_COL32(0, 0, 0, 200), name.c_str());
            dl->AddText(p, IM_COL32(255, 255, 255, 240), name.c_str());
        }
        char factor[32];
        std::snprintf(factor, sizeof factor, "\xc3\x97%s", formatNumber(g.factor).c_str());
        const ImVec2 fs = ImGui::CalcTextSize(factor);
        dl->AddRectFilled(ImVec2(at.x, at.y), ImVec2(at.x + fs.x + 8.0f, at.y + fs.y + 4.0f),
                          theme.background.packed());
        dl->AddText(ImVec2(at.x + 4.0f, at.y + 2.0f), theme.text.packed(), factor);
    }
    dl->PopClipRect();
    const ImU32 border = theme.text.packed();
    const float thick = std::max(1.0f, app.view.uiScale);
    dl->AddRect(at, end, border, 0.0f, 0, 2.0f * thick);
    // Where it is in the scene: its part of the world outlined.
    const double halfW = 0.5 * size.x / s, halfH = 0.5 * size.y / s;
    const Vec2 p0 = cam.worldToScreen({centre.x - halfW, centre.y + halfH});
    const Vec2 p1 = cam.worldToScreen({centre.x + halfW, centre.y - halfH});
    dl->AddRect(ImVec2(static_cast<float>(p0.x) - 1.0f, static_cast<float>(p0.y) - 1.0f),
                ImVec2(static_cast<float>(p1.x) + 1.0f, static_cast<float>(p1.y) + 1.0f), border,
                0.0f, 0, thick);
    const ScreenRect inset = spanning(at.x, at.y, end.x, end.y);
    placed.texts.push_back(inset);
    char mark[40];
    std::snprintf(mark, sizeof mark, "magnifier \xc3\x97%s", formatNumber(g.factor).c_str());
    app.view.shownMarks.push_back({mark, inset});
}

} // namespace

void drawMagnifier(App& app, ImDrawList* dl, Taken& placed) {
    app.view.shownMagnified.clear();
    const LessonStep* step = app.lesson.step();
    const World& world = app.sim.world();
    if (!step || world.blocks.size() > kMaxBlocks) return;
    const Camera& cam = app.view.camera;
    const ScreenRect& vp = cam.viewport();
    const double least = ImGui::GetIO().DisplaySize.x <= 1024.0f ? 28.0 : 40.0;
    const double target = 1.25 * least;
    const double ppm = cam.pixelsPerMetre();
    const std::string words = stepWords(*step);
    // The named blocks under the size, left to right, in groups that one inset shows whole.
    std::vector<std::size_t> small;
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        if (ppm * shortSide(b) >= least) continue;
        const Bounds box = boxOf(b);
        const Vec2 a = cam.worldToScreen(box.min), z = cam.worldToScreen(box.max);
        // Out of the view, or mostly (a "moment_camera" frames the evidence and leaves the
        // rest behind: the platformer's lift at its edge is not what the answer shows).
        const double w = std::min(z.x, vp.x + vp.width) - std::max(a.x, vp.x);
        const double h = std::min(a.y, vp.y + vp.height) - std::max(z.y, vp.y);
        if (w <= 0.0 || h <= 0.0 || w * h < 0.5 * (z.x - a.x) * (a.y - z.y)) continue;
        if (saysWord(words, app.sim.blockDisplayName(static_cast<int>(i)))) small.push_back(i);
    }
    if (small.empty()) return;
    std::sort(small.begin(), small.end(), [&world](std::size_t a, std::size_t b) {
        return world.blocks[a].position.x < world.blocks[b].position.x;
    });
    // Each joins the first group that still fits one inset with it, else starts one.
    std::vector<Group> groups;
    for (const std::size_t i : small) {
        const Block& b = world.blocks[i];
        bool joinedOne = false;
        for (Group& g : groups) {
            Group wider = g;
            wider.blocks.push_back(i);
            wider.box = joined(wider.box, boxOf(b));
            wider.factor = std::max(wider.factor, factorFor(ppm * shortSide(b), target));
            const double s = ppm * wider.factor;
            if ((wider.box.max.x - wider.box.min.x) * s + target <= kShare * vp.width &&
                (wider.box.max.y - wider.box.min.y) * s + target <= kShare * vp.height) {
                g = wider;
                joinedOne = true;
                break;
            }
        }
        if (!joinedOne) groups.push_back({{i}, boxOf(b), factorFor(ppm * shortSide(b), target)});
    }
    if (groups.size() > kMaxInsets) groups.resize(kMaxInsets);
    for (const Group& g : groups) drawInset(app, dl, placed, g, target);
}
