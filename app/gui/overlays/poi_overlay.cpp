// Point of impact of the watched block's last collision, as on the lecture's slides: the old
// position, the new position (overlapping: where it would be without the collision), the ghost at
// the point of impact POI = oldPosition + t·velocity with t = a/b, and beside it the "crooked"
// result of simply moving back along the collision axis only.
#include "app_frame.h"
#include "inspector_format.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

void box(const App& app, ImDrawList* dl, Vec2 centre, Vec2 size, Mark mark, float width,
         bool dashed) {
    const ImU32 color = uiMarkColor(mark);
    const ImVec2 a = toScreen(app, centre - size * 0.5), b = toScreen(app, centre + size * 0.5);
    const ImVec2 lo(std::min(a.x, b.x), std::min(a.y, b.y)),
        hi(std::max(a.x, b.x), std::max(a.y, b.y));
    if (!dashed) {
        dl->AddRectFilled(lo, hi, (color & 0x00FFFFFF) | 0x30000000);
        dl->AddRect(lo, hi, color, 0.0f, 0, width);
        return;
    }
    const float dash = 6.0f * app.view.uiScale;
    const ImVec2 corners[5] = {lo, ImVec2(hi.x, lo.y), hi, ImVec2(lo.x, hi.y), lo};
    for (int e = 0; e < 4; ++e) {
        const ImVec2 p = corners[e], q = corners[e + 1];
        const float len = std::abs(q.x - p.x) + std::abs(q.y - p.y);
        for (float s = 0.0f; s < len; s += 2.0f * dash) {
            const float t0 = s / len, t1 = std::min(1.0f, (s + dash) / len);
            dl->AddLine(ImVec2(p.x + (q.x - p.x) * t0, p.y + (q.y - p.y) * t0),
                        ImVec2(p.x + (q.x - p.x) * t1, p.y + (q.y - p.y) * t1), color, width);
        }
    }
}

void label(ImDrawList* dl, ImVec2 at, Mark mark, const std::string& text) {
    if (!uiLightTheme())
        dl->AddText(ImVec2(at.x + 1, at.y + 1), IM_COL32(0, 0, 0, 230), text.c_str());
    dl->AddText(at, uiMarkColor(mark), text.c_str());
}

bool poiShown(const App& app) {
    const PoiView& p = app.sim.run.poi;
    return app.view.show.poi && p.valid && p.block >= 0 &&
           p.block < static_cast<int>(app.sim.world().blocks.size());
}

} // namespace

std::vector<ScreenRect> poiBoxesOnScreen(const App& app) {
    if (!poiShown(app)) return {};
    const PoiView& p = app.sim.run.poi;
    std::vector<ScreenRect> out;
    for (const Vec2 c : {p.oldPosition, p.ghost, p.crooked, p.newPosition}) {
        const ImVec2 a = toScreen(app, c - p.size * 0.5), b = toScreen(app, c + p.size * 0.5);
        out.push_back(
            {std::min(a.x, b.x), std::min(a.y, b.y), std::abs(b.x - a.x), std::abs(b.y - a.y)});
    }
    return out;
}

void drawPoiOverlay(App& app) {
    const SceneLabelFont font(app);
    const PoiView& p = app.sim.run.poi;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const float s = app.view.uiScale;
    if (!poiShown(app)) {
        // On a plate as the numbers are, wrapped to the scene's width where it is narrow.
        drawSceneCaption(app,
                         {{"Point of impact: shown after the watched block's next collision",
                           uiMarkColor(Mark::PoiOld), true}},
                         {});
        return;
    }
    const float w = 2.0f * s;
    // The path of the frame, old centre to new centre.
    dl->AddLine(toScreen(app, p.oldPosition), toScreen(app, p.newPosition),
                uiMarkColor(Mark::PoiOld), 1.5f * s);
    box(app, dl, p.oldPosition, p.size, Mark::PoiOld, w, true);
    box(app, dl, p.newPosition, p.size, Mark::PoiNew, w, true);
    box(app, dl, p.crooked, p.size, Mark::PoiMovedBack, w, false);
    box(app, dl, p.ghost, p.size, Mark::PoiContact, w * 1.3f, false);
    // The four boxes are taken on screen: no label (theirs, the arrows' values drawn before, the
    // overlays' after) goes over one (a label over its own box hid the box: steps 4 and 20 of
    // lecture3). Each label beside its own box, on the first free side of its order (old above,
    // new right, POI left, moved back right or below), else where placeSceneLabel finds room.
    struct Marked {
        Vec2 centre;
        const char* text;
        Mark mark;
        int sides[4]; // 0 above, 1 right, 2 left, 3 below
    };
    const bool movedBack = length(p.crooked - p.ghost) > 1e-9;
    const Marked marks[4] = {{p.oldPosition, "old", Mark::PoiOld, {0, 2, 1, 3}},
                             {p.ghost, "POI", Mark::PoiContact, {2, 0, 3, 1}},
                             {p.crooked, "moved back", Mark::PoiMovedBack, {1, 3, 0, 2}},
                             {p.newPosition, "new", Mark::PoiNew, {1, 3, 2, 0}}};
    const std::vector<ScreenRect> boxes = poiBoxesOnScreen(app); // in the order of `marks`
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        if (marks[k].mark == Mark::PoiMovedBack && !movedBack) continue;
        app.ui.takenOnScreen.blocks.push_back(boxes[k]);
        app.view.shownMarks.push_back({marks[k].text, boxes[k]});
    }
    // The caption: the numbers of t = a/b. Placed before the boxes' labels, which go around it
    // (placed after them, it found no room in a narrow scene: step 5 of lecture3 at 1280x800, UI
    // 1.5); it keeps off the boxes and a line and a half around them, their labels' room.
    const char axis = p.axis == 0 ? 'x' : 'y';
    const std::string other = p.other < 0 ? wallName(p.other) : app.sim.blockDisplayName(p.other);
    const std::string lines[4] = {
        "Point of impact of " + app.sim.blockDisplayName(p.block) + " with " + other +
            ", frame from t = " + formatNumber(p.frameStart) + " s",
        poiEquation(p),
        "POI = old + t·v·dt = (" + formatNumber(p.ghost.x) + ", " + formatNumber(p.ghost.y) + ")",
        std::string("moved back along ") + axis + " only: (" + formatNumber(p.crooked.x) + ", " +
            formatNumber(p.crooked.y) + "), crooked",
    };
    // Where the scene is narrow (1024x768 at UI 1.25, 1280x720 at 1.5: 300-390 px of text), the
    // same numbers in fewer words (four lines of at most about 35 characters: a plate that fits
    // above or under the blocks there): the title without "Point of impact" (the step and the
    // boxes' labels say it), the equation without its units' note, the crooked result without
    // its name.
    const std::string brief[4] = {
        app.sim.blockDisplayName(p.block) + " with " + other + ", frame from " +
            formatNumber(p.frameStart) + " s",
        poiEquation(p, false),
        "",
        std::string("moved back along ") + axis + " only: (" + formatNumber(p.crooked.x) + ", " +
            formatNumber(p.crooked.y) + ")",
    };
    const ImU32 colors[4] = {uiThemed(IM_COL32(230, 234, 242, 255)), uiMarkColor(Mark::PoiContact),
                             uiMarkColor(Mark::PoiContact), uiMarkColor(Mark::PoiMovedBack)};
    std::vector<CaptionLine> caption;
    for (int i = 0; i < 4; ++i) caption.push_back({lines[i], colors[i], true, brief[i]});
    std::vector<WorldBox> inWorld;
    for (Vec2 c : {p.oldPosition, p.newPosition, p.ghost, p.crooked})
        inWorld.push_back({c, p.size});
    drawSceneCaption(app, caption, inWorld);
    const float hw = static_cast<float>(app.view.camera.metresToPixels(p.size.x * 0.5));
    const float hh = static_cast<float>(app.view.camera.metresToPixels(p.size.y * 0.5));
    for (const Marked& m : marks) {
        if (m.mark == Mark::PoiMovedBack && !movedBack) continue;
        const ImVec2 sc = toScreen(app, m.centre);
        const ImVec2 ts = ImGui::CalcTextSize(m.text);
        // Above and below 4 px (x UI scale) off the box; beside it, past the half line that
        // keeps a label apart from what it is not (placeSceneLabelAtOneOf, freeSpot).
        const float g = 4.0f * s, beside = ImGui::GetFontSize() * 0.5f + g;
        std::vector<ImVec2> tries;
        for (const int side : m.sides) {
            tries.push_back(side == 0   ? ImVec2(sc.x - ts.x * 0.5f, sc.y - hh - ts.y - g)
                            : side == 1 ? ImVec2(sc.x + hw + beside, sc.y - ts.y * 0.5f)
                            : side == 2 ? ImVec2(sc.x - hw - beside - ts.x, sc.y - ts.y * 0.5f)
                                        : ImVec2(sc.x - ts.x * 0.5f, sc.y + hh + g));
        }
        label(dl, placeSceneLabelAtOneOf(app, tries, ts), m.mark, m.text);
    }
}
