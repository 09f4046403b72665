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

} // namespace

void drawPoiOverlay(App& app) {
    const SceneLabelFont font(app);
    const PoiView& p = app.sim.run.poi;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const float s = app.view.uiScale;
    if (!p.valid || p.block < 0 || p.block >= static_cast<int>(app.sim.world().blocks.size())) {
        const char* text = "Point of impact: shown after the watched block's next collision";
        const ImVec2 size = ImGui::CalcTextSize(text);
        label(dl, sceneCaptionPlace(app, size.x, size.y, {}), Mark::PoiOld, text);
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
    // Each label on its own side of its box: old above, new right, POI left, moved back below.
    const float hw = static_cast<float>(app.view.camera.metresToPixels(p.size.x * 0.5));
    const float hh = static_cast<float>(app.view.camera.metresToPixels(p.size.y * 0.5));
    auto place = [&](Vec2 c, const char* text, Mark mark, int side) {
        const ImVec2 sc = toScreen(app, c);
        const ImVec2 ts = ImGui::CalcTextSize(text);
        const float g = 4.0f * s;
        const ImVec2 at = side == 0   ? ImVec2(sc.x - ts.x * 0.5f, sc.y - hh - ts.y - g)
                          : side == 1 ? ImVec2(sc.x + hw + g, sc.y - ts.y * 0.5f)
                          : side == 2 ? ImVec2(sc.x - hw - g - ts.x, sc.y - ts.y * 0.5f)
                                      : ImVec2(sc.x - ts.x * 0.5f, sc.y + hh + g);
        label(dl, placeSceneLabel(app, at, ts), mark, text);
    };
    place(p.oldPosition, "old", Mark::PoiOld, 0);
    place(p.newPosition, "new", Mark::PoiNew, 1);
    place(p.ghost, "POI", Mark::PoiContact, 2);
    if (length(p.crooked - p.ghost) > 1e-9) place(p.crooked, "moved back", Mark::PoiMovedBack, 3);

    // The caption: the numbers of t = a/b.
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
    const ImU32 colors[4] = {uiThemed(IM_COL32(230, 234, 242, 255)), uiMarkColor(Mark::PoiContact),
                             uiMarkColor(Mark::PoiContact), uiMarkColor(Mark::PoiMovedBack)};
    std::vector<CaptionLine> caption;
    for (int i = 0; i < 4; ++i) caption.push_back({lines[i], colors[i], true});
    std::vector<WorldBox> boxes;
    for (Vec2 c : {p.oldPosition, p.newPosition, p.ghost, p.crooked}) boxes.push_back({c, p.size});
    drawSceneCaption(app, caption, boxes);
}
