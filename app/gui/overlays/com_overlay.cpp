// Centre of mass of the dynamic blocks with its velocity u (= total momentum / total mass), drawn
// in the scene, and the momenta diagram: every block's momentum tip to tail and their sum, as
// teachers draw it (PhET's Collision Lab). In the centre-of-mass frame (view_frame.h) the marker
// stands still and the diagram adds m·w: it closes, total momentum zero in that frame.
#include "app_frame.h"
#include "number_text.h"
#include "overlay_window.h"
#include "renderer.h"
#include "text_format.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr std::size_t kDiagramArrowsWithHeads = 40;
// Segments of the chain drawn at most (a software rasteriser pays for each).
constexpr std::size_t kDiagramSegments = 200;

void arrow(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 color, float width, float head) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    const float len = std::sqrt(dx * dx + dy * dy);
    if (len < 1.0f) return;
    const float ux = dx / len, uy = dy / len;
    const float h = std::min(head, len * 0.6f);
    const ImVec2 base(b.x - ux * h, b.y - uy * h);
    dl->AddLine(a, base, color, width);
    dl->AddTriangleFilled(b, ImVec2(base.x - uy * h * 0.5f, base.y + ux * h * 0.5f),
                          ImVec2(base.x + uy * h * 0.5f, base.y - ux * h * 0.5f), color);
}

void drawMomentaDiagram(App& app) {
    OverlayWindow overlay(app, OverlayId::com);
    if (!overlay) return;
    const World& w = app.sim.world();
    const Vec2 u = frameVelocity(w, app.view.frame);
    // Tip to tail, in file order; the extent fixes the scale.
    std::vector<Vec2> tips{Vec2{}};
    std::vector<int> owner;
    for (std::size_t i = 0; i < w.blocks.size(); ++i) {
        const Block& b = w.blocks[i];
        if (!b.isDynamic()) continue;
        tips.push_back(tips.back() + (b.velocity - u) * b.mass);
        owner.push_back(static_cast<int>(i));
    }
    const Vec2 total = tips.back();
    // Rounding noise reads 0 (in the centre-of-mass frame the sum is zero but for it).
    double sum = 0.0;
    for (std::size_t k = 1; k < tips.size(); ++k) sum += length(tips[k] - tips[k - 1]);
    const std::string text = "total p = (" + formatNumber(total.x, sum) + ", " +
                             formatNumber(total.y, sum) + ") kg·m/s" +
                             (app.view.frame == ViewFrame::World ? "" : " (centre-of-mass frame)");
    dimText(text.c_str());
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    ImGui::InvisibleButton("##momenta", ImVec2(std::max(avail.x, 40.0f), std::max(avail.y, 40.0f)));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    dl->AddRectFilled(lo, hi, plotAreaColor(uiLightTheme()).packed(), 3.0f);
    Vec2 mn{0.0, 0.0}, mx{0.0, 0.0};
    for (const Vec2& t : tips) {
        mn = Vec2{std::min(mn.x, t.x), std::min(mn.y, t.y)};
        mx = Vec2{std::max(mx.x, t.x), std::max(mx.y, t.y)};
    }
    const double span = std::max({mx.x - mn.x, mx.y - mn.y, 1e-9});
    const float pad = ImGui::GetFontSize();
    const double scale = std::min((hi.x - lo.x - 2 * pad) / std::max(mx.x - mn.x, span * 0.2),
                                  (hi.y - lo.y - 2 * pad) / std::max(mx.y - mn.y, span * 0.2));
    const ImVec2 centre((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    const Vec2 mid = (mn + mx) * 0.5;
    auto map = [&](Vec2 p) {
        return ImVec2(centre.x + static_cast<float>((p.x - mid.x) * scale),
                      centre.y - static_cast<float>((p.y - mid.y) * scale));
    };
    const float width = std::max(2.0f, ImGui::GetFontSize() * 0.14f);
    const float head = ImGui::GetFontSize() * 0.7f;
    const bool heads = owner.size() <= kDiagramArrowsWithHeads;
    // With many blocks one drawn segment sums `group` consecutive momenta: its ends are partial
    // sums, so the chain still ends at the total, in at most kDiagramSegments lines.
    const std::size_t group =
        heads ? 1
              : std::max<std::size_t>(1, (owner.size() + kDiagramSegments - 1) / kDiagramSegments);
    for (std::size_t k = 0; k < owner.size(); k += group) {
        const std::size_t next = std::min(k + group, owner.size());
        const ImU32 c = app.sim.blockDisplayColor(owner[k]).withAlpha(0.95f).packed();
        if (heads)
            arrow(dl, map(tips[k]), map(tips[next]), c, width, head);
        else
            dl->AddLine(map(tips[k]), map(tips[next]), c, 1.0f);
    }
    // The total beside the chain (shifted a little), so collinear momenta stay readable.
    const float shift = ImGui::GetFontSize() * 0.6f;
    ImVec2 a = map(Vec2{}), b = map(total);
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    const ImVec2 off = len > 1.0f ? ImVec2(-dy / len * shift, dx / len * shift) : ImVec2(0, 0);
    a = ImVec2(a.x + off.x, a.y + off.y);
    b = ImVec2(b.x + off.x, b.y + off.y);
    arrow(dl, a, b, uiMarkColor(Mark::Total), width * 1.3f, head * 1.2f);
    dl->AddCircleFilled(map(Vec2{}), width * 1.5f, uiMarkColor(Mark::Total));
    if (len > 1.0f) {
        // Beside the total's middle, on the side away from the chain, its nearest edge half a
        // shift clear of the arrow (a label centred on the line was cut by it: "tota|").
        const char* text = "total";
        const ImVec2 ts = ImGui::CalcTextSize(text);
        const ImVec2 n(off.x / shift, off.y / shift);
        const float reach =
            std::abs(n.x) * ts.x * 0.5f + std::abs(n.y) * ts.y * 0.5f + width + shift * 0.5f;
        const float x = (a.x + b.x - ts.x) * 0.5f + n.x * reach;
        const float y = (a.y + b.y - ts.y) * 0.5f + n.y * reach;
        dl->AddText(ImVec2(std::clamp(x, lo.x, std::max(lo.x, hi.x - ts.x)),
                           std::clamp(y, lo.y, std::max(lo.y, hi.y - ts.y))),
                    uiMarkColor(Mark::Total), text);
    }
}

// The marker's radius, px.
float markerRadius(const App& app) {
    return 9.0f * app.view.uiScale;
}

// Where the centre of mass's velocity arrow ends (m): u, or w = 0 in its own frame.
Vec2 comArrowTip(const App& app, const CentreOfMass& c) {
    return c.position +
           (c.velocity - frameVelocity(app.sim.world(), app.view.frame)) * kVelocityArrowScale;
}

} // namespace

std::vector<ScreenRect> comMarkerOnScreen(const App& app) {
    const CentreOfMass c = centreOfMass(app.sim.world());
    if (!app.view.show.com || !c.valid) return {};
    const ImVec2 p = toScreen(app, c.position), head = toScreen(app, comArrowTip(app, c));
    const float r = markerRadius(app), hw = 7.0f * app.view.uiScale; // the head, half its width
    return {{p.x - r, p.y - r, 2.0f * r, 2.0f * r},
            {std::min(p.x, head.x) - hw, std::min(p.y, head.y) - hw,
             std::abs(head.x - p.x) + 2.0f * hw, std::abs(head.y - p.y) + 2.0f * hw}};
}

void drawComOverlay(App& app) {
    const CentreOfMass c = centreOfMass(app.sim.world());
    if (c.valid) {
        const SceneLabelFont font(app);
        ImDrawList* dl = ImGui::GetBackgroundDrawList();
        const ImVec2 p = toScreen(app, c.position);
        const float r = markerRadius(app);
        const ImU32 col = uiMarkColor(Mark::CentreOfMass);
        // In its own frame the centre of mass stands still: no arrow.
        const Vec2 tip = comArrowTip(app, c);
        arrow(dl, p, toScreen(app, tip), col, 3.0f * app.view.uiScale, 13.0f * app.view.uiScale);
        dl->AddCircleFilled(
            p, r, uiLightTheme() ? IM_COL32(255, 255, 255, 220) : IM_COL32(20, 20, 20, 220));
        dl->AddCircle(p, r, col, 20, 2.5f * app.view.uiScale);
        dl->AddLine(ImVec2(p.x - r, p.y), ImVec2(p.x + r, p.y), col, 2.0f);
        dl->AddLine(ImVec2(p.x, p.y - r), ImVec2(p.x, p.y + r), col, 2.0f);
        // The marker and its arrow are taken on screen (by the scene's labels, drawn before,
        // too): no label goes over them.
        const std::vector<ScreenRect> taken = comMarkerOnScreen(app);
        for (const ScreenRect& box : taken) app.ui.takenOnScreen.blocks.push_back(box);
        app.view.shownMarks.push_back({"centre of mass", taken.front()});
        // On one line, or two where one would take more than a third of the scene's width (a
        // 1024x768 projector: it ran past the scene's edge and over m2).
        // ("u = (%.2f, %.2f) m/s", number_text.h)
        std::string u = "u = (";
        number_text::appendFixed(u, c.velocity.x, 2);
        u += ", ";
        number_text::appendFixed(u, c.velocity.y, 2);
        u += ") m/s";
        std::string line = "centre of mass  " + u;
        if (ImGui::CalcTextSize(line.c_str()).x > app.view.camera.viewport().width / 3.0)
            line = "centre of mass\n" + u;
        const char* text = line.c_str();
        // Beside the marker on its first free side (right, below, left, above); where none is
        // free, where placeSceneLabel finds room, with a leader line to the marker (lecture3 step
        // 10 wrote it over m2, whom it does not name).
        const ImVec2 ts = ImGui::CalcTextSize(text);
        const float g = 4.0f * app.view.uiScale;
        const std::vector<ImVec2> tries = {ImVec2(p.x + r + g, p.y - ts.y * 0.5f),
                                           ImVec2(p.x - ts.x * 0.5f, p.y + r + g),
                                           ImVec2(p.x - r - g - ts.x, p.y - ts.y * 0.5f),
                                           ImVec2(p.x - ts.x * 0.5f, p.y - r - g - ts.y)};
        const ImVec2 at = placeSceneLabelAtOneOf(app, tries, ts);
        // The label's point nearest the marker; a leader line where it is not beside it.
        const ImVec2 near(std::clamp(p.x, at.x, at.x + ts.x), std::clamp(p.y, at.y, at.y + ts.y));
        const float dx = near.x - p.x, dy = near.y - p.y, d = std::sqrt(dx * dx + dy * dy);
        if (d > r + 2.0f * g) {
            dl->AddLine(ImVec2(p.x + dx / d * r, p.y + dy / d * r), near, col,
                        1.5f * app.view.uiScale);
        }
        if (!uiLightTheme()) dl->AddText(ImVec2(at.x + 1, at.y + 1), IM_COL32(0, 0, 0, 220), text);
        dl->AddText(at, col, text);
    }
    drawMomentaDiagram(app);
}
