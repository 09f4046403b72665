// A student's trace over the reference (issue 29, docs/compare.md): their blocks at the frame
// shown as outlines (drawn by the scene renderer: app_frame.cpp hands it the student's world),
// and here what says how far apart they are: a line from each reference block to the student's
// where they differ, "yours" beside the outline, and a caption with the frame and the first
// difference. Nothing is drawn while no trace is open.
#include "app_frame.h"
#include "overlay_window.h"
#include "report.h"
#include "text_format.h"
#include "ui_style.h"

#include <cmath>
#include <string>
#include <vector>

namespace {

// How far apart two positions are: the larger difference of the two axes (m).
double apart(Vec2 a, Vec2 b) {
    return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y));
}

} // namespace

void drawGhostOverlay(App& app) {
    const StudentTrace& st = app.studentTrace;
    if (!st.open()) return;
    const SceneLabelFont font(app);
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const float s = app.view.uiScale;
    const ImU32 color = studentTraceColor().packed();
    const TraceComparison& c = *st.comparison;
    const auto frame = static_cast<std::int64_t>(app.sim.world().frame);
    const TraceRow* row = st.rowAt(frame);
    std::vector<WorldBox> boxes;
    std::string now;
    if (row) {
        int differing = 0;
        double worst = 0.0;
        for (std::size_t b = 0; b < st.trace->blocks.size(); ++b) {
            const auto index = static_cast<std::size_t>(st.trace->blocks[b]);
            if (index >= app.sim.world().blocks.size()) continue;
            const Block& ref = app.sim.world().blocks[index];
            const Vec2 yours = row->position[b];
            boxes.push_back({yours, ref.size});
            const double d = apart(yours, ref.position);
            worst = std::max(worst, d);
            if (d <= c.tolerance.position) continue;
            ++differing;
            dl->AddLine(toScreen(app, ref.position), toScreen(app, yours), uiThemed(color),
                        1.5f * s);
            if (differing > 8) continue; // a crowd: the lines say enough
            const ImVec2 at = toScreen(app, yours);
            const char* text = "yours";
            const ImVec2 size = ImGui::CalcTextSize(text);
            dl->AddText(
                placeSceneLabel(app, ImVec2(at.x - size.x * 0.5f, at.y - size.y * 0.5f), size),
                uiThemed(color), text);
        }
        now = differing == 0 ? "your blocks are the reference's (within " +
                                   formatQuantity(c.tolerance.position, "m") + ")"
                             : std::to_string(differing) +
                                   (differing == 1 ? " block apart, " : " blocks apart, ") +
                                   "up to " + formatQuantity(worst, "m");
    } else {
        now = "your trace has no row for this frame";
    }
    std::vector<CaptionLine> lines;
    lines.push_back({"Your trace (outlines), frame " + std::to_string(frame) + ": " + now,
                     IM_COL32(230, 234, 242, 255)});
    if (c.same())
        lines.push_back(
            {"the same as the reference over its " + std::to_string(c.frames) + " frames", color});
    else
        lines.push_back(
            {"first difference: frame " + std::to_string(c.match.first().frame) + ", " +
                 differenceName(st.scene, c.match.first()) + " off by " +
                 formatQuantity(c.match.first().by(), c.match.first().velocity ? "m/s" : "m"),
             color});
    drawSceneCaption(app, lines, boxes);
}
