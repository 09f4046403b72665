// The velocity-space window (explain/velocity_space.h): for two dynamic blocks, their state as a
// point at (sqrt(m1)·v1, sqrt(m2)·v2) with its path, the kinetic energy's circle, the momentum's
// line and the block-block reflection line; the caption says why high_mass_ratio counts pi. A
// button writes the path as CSV. Other scenes get the reason in the window.
#include "app_frame.h"
#include "csv_export.h"
#include "overlay_window.h"
#include "text_format.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace {

// Points of the path drawn at most (a software rasteriser pays for each).
constexpr std::size_t kPathSegments = 3000;
constexpr std::size_t kChords = 40; // the path's last steps drawn as lines
constexpr ImU32 kAxes = IM_COL32(255, 255, 255, 70);

void dashedLine(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 color, float dash, float width) {
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    if (len < 1.0f) return;
    for (float s = 0.0f; s < len; s += 2.0f * dash) {
        const float e = std::min(s + dash, len);
        dl->AddLine(ImVec2(a.x + dx * s / len, a.y + dy * s / len),
                    ImVec2(a.x + dx * e / len, a.y + dy * e / len), color, width);
    }
}

// The picture in the square [lo, lo + side].
void drawPicture(App& app, const VelocitySpacePath& path, ImVec2 lo, float side) {
    const VelocitySpacePair& pair = path.pair();
    const World& w = app.sim.world();
    const double v1 = w.blocks[static_cast<std::size_t>(pair.block1)].velocity.x;
    const double v2 = w.blocks[static_cast<std::size_t>(pair.block2)].velocity.x;
    const Vec2 now = velocitySpacePoint(pair, v1, v2);
    // The extent: the largest circle the path met (energy only decreases in these scenes).
    double extent = length(now);
    for (const VelocitySpaceSample& s : path.samples())
        extent = std::max(extent, length(velocitySpacePoint(pair, s.v1, s.v2)));
    if (!(extent > 0.0) || !std::isfinite(extent)) extent = 1.0;
    extent *= 1.12;
    const float font = ImGui::GetFontSize();
    const ImVec2 centre(lo.x + side * 0.5f, lo.y + side * 0.5f);
    const double scale = (side * 0.5 - font * 0.3) / extent;
    const auto map = [&](Vec2 p) {
        return ImVec2(centre.x + static_cast<float>(p.x * scale),
                      centre.y - static_cast<float>(p.y * scale));
    };
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 hi(lo.x + side, lo.y + side);
    dl->AddRectFilled(lo, hi, plotAreaColor(uiLightTheme()).packed(), 3.0f);
    dl->PushClipRect(lo, hi, true);
    // Axes: a wall hit flips one coordinate, a reflection across the other axis.
    dl->AddLine(ImVec2(lo.x, centre.y), ImVec2(hi.x, centre.y), uiThemed(kAxes), 1.0f);
    dl->AddLine(ImVec2(centre.x, lo.y), ImVec2(centre.x, hi.y), uiThemed(kAxes), 1.0f);
    const float width = std::max(1.5f, font * 0.1f);
    // The block-block reflection line, through the origin along (sqrt(m1), sqrt(m2)).
    const Vec2 n = normalized(Vec2{std::sqrt(pair.m1), std::sqrt(pair.m2)});
    dashedLine(dl, map(n * (-2.0 * extent)), map(n * (2.0 * extent)), uiMarkColor(Mark::Reflection),
               font * 0.4f, width);
    // The path: every state a dot (thinned to at most kPathSegments), the last kChords steps
    // as lines (thousands of chords would fill the disc; the dots show where they land).
    const auto& samples = path.samples();
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / kPathSegments);
    for (std::size_t k = 0; k < samples.size(); k += stride)
        dl->AddCircleFilled(map(velocitySpacePoint(pair, samples[k].v1, samples[k].v2)),
                            width * 0.8f, uiMarkColor(Mark::VelocityPath), 6);
    const std::size_t first = samples.size() > kChords ? samples.size() - kChords : 0;
    for (std::size_t k = first + 1; k < samples.size(); ++k) {
        dl->AddLine(map(velocitySpacePoint(pair, samples[k - 1].v1, samples[k - 1].v2)),
                    map(velocitySpacePoint(pair, samples[k].v1, samples[k].v2)),
                    uiMarkColor(Mark::VelocityPath), 1.0f);
    }
    // Kinetic energy: the circle through the state, radius sqrt(2·KE).
    const float r = static_cast<float>(length(now) * scale);
    if (r > 1.0f) dl->AddCircle(centre, r, uiMarkColor(Mark::Kinetic), 64, width);
    // Momentum: the line sqrt(m1)·x + sqrt(m2)·y = p through the state, across n.
    const Vec2 t = perpendicular(n); // over the path, as the circle
    dl->AddLine(map(now - t * (3.0 * extent)), map(now + t * (3.0 * extent)),
                uiMarkColor(Mark::Momentum), width);
    dl->AddCircleFilled(map(now), font * 0.3f, uiThemed(IM_COL32(255, 255, 255, 240)));
    // Axis names, where there is room for them (the caption names the axes too).
    if (side < 9.0f * font) {
        dl->PopClipRect();
        return;
    }
    const std::string s1 = formulaSymbol(baseBlockName(app.sim.blockDisplayName(pair.block1)));
    const std::string s2 = formulaSymbol(baseBlockName(app.sim.blockDisplayName(pair.block2)));
    const std::string xName = "sqrt(m" + (s1.empty() ? "1" : s1) + ")·v" + (s1.empty() ? "1" : s1);
    const std::string yName = "sqrt(m" + (s2.empty() ? "2" : s2) + ")·v" + (s2.empty() ? "2" : s2);
    const ImU32 text = uiThemed(IM_COL32(200, 206, 220, 255));
    const ImVec2 xs = ImGui::CalcTextSize(xName.c_str());
    dl->AddText(ImVec2(hi.x - xs.x - 3.0f, centre.y + 2.0f), text, xName.c_str());
    const float yw = ImGui::CalcTextSize(yName.c_str()).x;
    dl->AddText(
        ImVec2(std::max(lo.x + 2.0f, std::min(centre.x + 4.0f, hi.x - yw - 2.0f)), lo.y + 2.0f),
        text, yName.c_str());
    dl->PopClipRect();
}

} // namespace

void drawVelocitySpaceOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::velocitySpace);
    if (!overlay) return;
    const VelocitySpacePath& path = app.sim.telemetry.velocitySpace;
    const VelocitySpacePair& pair = path.pair();
    if (!pair.valid()) {
        textWrappedAtSpaces(velocitySpacePair(app.sim.world()).why);
        return;
    }
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // The square on the left and the caption beside it when the window is wide, else the
    // caption under a smaller square.
    const bool beside = avail.x > avail.y * 1.8f;
    // Stacked, the picture comes first, the CSV row under it (the caption where it fits).
    const float row = ImGui::GetFrameHeightWithSpacing() + 2.0f * ImGui::GetStyle().WindowPadding.y;
    const float side = std::max(40.0f, beside ? avail.y : std::min(avail.x, avail.y - row));
    const ImVec2 lo = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##velocityspace", ImVec2(side, side));
    const std::string caption = velocitySpaceCaption(pair);
    wrappedTooltip(caption);
    drawPicture(app, path, lo, side);
    if (beside) ImGui::SameLine();
    // Padded: a glyph's left bearing at the child's very edge would be cut.
    ImGui::BeginChild("##velocityspace-caption", ImVec2(0.0f, 0.0f), false,
                      ImGuiWindowFlags_AlwaysUseWindowPadding);
    if (uiSmallButton("CSV")) {
        exportCsv(app, "velocity space",
                  velocitySpaceTable(path, app.sim.blockDisplayName(pair.block1),
                                     app.sim.blockDisplayName(pair.block2)));
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Write the path (t, v1, v2 and the coordinates) as a CSV file");
    ImGui::SameLine();
    ImGui::TextDisabled("%zu points", path.samples().size());
    // The whole caption where it fits; else the count (theta and N) where it fits; the whole on
    // hovering the picture or the count.
    const ImVec2 room = ImGui::GetContentRegionAvail();
    const auto wrapped = [&room](const std::string& text) {
        return wrapFormula(text, room.x, [](const std::string& line) {
            return static_cast<double>(ImGui::CalcTextSize(line.c_str()).x);
        });
    };
    const auto fits = [&room](const std::string& text) {
        return ImGui::CalcTextSize(text.c_str()).y <= room.y;
    };
    const std::string whole = wrapped(caption), count = wrapped(velocitySpaceCount(pair));
    if (fits(whole)) {
        ImGui::TextUnformatted(whole.c_str());
    } else if (fits(count)) {
        ImGui::TextUnformatted(count.c_str());
        wrappedTooltip(caption);
    }
    ImGui::EndChild();
}
