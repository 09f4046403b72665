#include "plot_widget.h"

#include "dock_layout.h" // kMinPlotShare
#include "palette.h"
#include "ui_style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

// The plot's colours in the current theme (the light one: a white plot area, dark lines).
ImU32 frameBg() {
    return plotAreaColor(uiLightTheme()).packed();
}
ImU32 gridColor() {
    return uiLightTheme() ? IM_COL32(0, 0, 0, 30) : IM_COL32(255, 255, 255, 28);
}
ImU32 zeroColor() {
    return uiLightTheme() ? IM_COL32(0, 0, 0, 90) : IM_COL32(255, 255, 255, 70);
}
ImU32 axisText() {
    return uiThemed(IM_COL32(190, 198, 215, 255));
}
ImU32 markerColor() {
    return uiThemed(IM_COL32(255, 196, 80, 80));
}
ImU32 cursorColor() {
    return uiThemed(IM_COL32(120, 220, 255, 230));
}
constexpr std::size_t kMaxMarkers = 150;
// A band (PlotSeries::band): this many line widths wide, in its colour at about half opacity.
constexpr float kBandWidth = 4.0f;
ImU32 bandColor(ImU32 color) {
    const ImU32 alpha = ((color >> IM_COL32_A_SHIFT) & 0xFF) * 5 / 10;
    return (color & ~IM_COL32_A_MASK) | (alpha << IM_COL32_A_SHIFT);
}

// A series' line in its dash pattern (dashPieces), the dashes' unit scaled with the line.
void polyline(ImDrawList* dl, const std::vector<ImVec2>& points, ImU32 color, Dash dash,
              float thickness) {
    if (dash == Dash::Solid) {
        dl->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, thickness);
        return;
    }
    std::vector<PlotPoint> line;
    line.reserve(points.size());
    for (const ImVec2& p : points) line.push_back({p.x, p.y});
    std::vector<ImVec2> piece;
    for (const std::vector<PlotPoint>& part : dashPieces(line, dash, 2.0f * thickness)) {
        piece.clear();
        for (const PlotPoint& p : part) piece.emplace_back(p.x, p.y);
        dl->AddPolyline(piece.data(), static_cast<int>(piece.size()), color, 0, thickness);
    }
}
constexpr float kColumnPx = 2.0f; // series thinned to their extremes per column this wide

double axisValue(double v, bool log) {
    if (!log) return v;
    return v > 0.0 ? std::log10(v) : NAN;
}

struct Mapping {
    double x0, x1, y0, y1; // data (log10 when log)
    ImVec2 min, max;       // plot area, px
    float sx(double x) const { return min.x + float((x - x0) / (x1 - x0)) * (max.x - min.x); }
    float sy(double y) const { return max.y - float((y - y0) / (y1 - y0)) * (max.y - min.y); }
};

// A linear axis labels at least kMinYTicks values (issue 23: not just "0").
constexpr int kMinYTicks = 3;

std::vector<double> ticksFor(double lo, double hi, bool log, int minTicks, int maxTicks) {
    return log ? decadeTicks(lo, hi, maxTicks)
               : ticksEvery(lo, hi, axisTickStep(lo, hi, minTicks, maxTicks));
}

std::string labelFor(double v, double lo, double hi, bool log, int minTicks, int maxTicks) {
    if (log) return decadeLabel(v);
    return tickLabel(v, axisTickStep(lo, hi, minTicks, maxTicks));
}

// Every how many y ticks a number is written so that the numbers, each `lineHeight` px tall,
// never touch (the ticks are evenly spaced, on a log axis too: decades).
std::size_t labelStride(const std::vector<double>& ticks, const Mapping& m, float lineHeight) {
    if (ticks.size() < 2) return 1;
    const float gap = std::abs(m.sy(ticks[1]) - m.sy(ticks[0]));
    if (!(gap > 0.0f)) return ticks.size();
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(lineHeight / gap)));
}

// The first numbered tick, given every `stride`-th is: the offset that numbers the most ticks,
// the one that numbers "0" among them (a 55 px plot of -4..4 in steps of 2 writes "-4" and "2"
// rather than "0" alone: issue 23 asked for more than "0").
std::size_t firstLabelled(const std::vector<double>& ticks, std::size_t stride) {
    std::size_t zero = 0;
    for (std::size_t k = 0; k < ticks.size(); ++k)
        if (ticks[k] == 0.0) zero = k;
    std::size_t best = zero % stride;
    const auto count = [&](std::size_t from) {
        return (ticks.size() - from + stride - 1) / stride;
    };
    for (std::size_t from = 0; from < stride && from < ticks.size(); ++from)
        if (count(from) > count(best)) best = from;
    return best;
}

// One piece of a plot's header: the title, the unit, or a series' legend entry (line and label).
struct HeaderItem {
    std::string text;
    ImU32 color = 0;
    const PlotSeries* series = nullptr; // a legend entry
    float x = 0.0f, y = 0.0f;
    int line = 0;
};

// Places the title, the unit and the legend from `left` to `right`, starting a new line (each
// 1.35 font sizes below the last) where the next piece does not fit.
std::vector<HeaderItem> layoutHeader(const PlotOptions& o, const std::vector<PlotSeries>& series,
                                     float left, float right, float top) {
    const float font = ImGui::GetFontSize();
    std::vector<HeaderItem> items;
    if (*o.title) items.push_back({o.title, uiThemed(IM_COL32(235, 238, 245, 255))});
    if (*o.yUnit) items.push_back({std::string("[") + o.yUnit + "]", axisText()});
    for (const PlotSeries& ps : series) {
        if (!ps.label.empty()) items.push_back({ps.label, 0, &ps});
    }
    float x = left;
    int line = 0;
    for (HeaderItem& it : items) {
        const float width =
            ImGui::CalcTextSize(it.text.c_str()).x + (it.series ? font * 1.2f : 0.0f);
        if (x > left && x + width > right) {
            x = left;
            ++line;
        }
        it.x = x;
        it.line = line;
        it.y = top + float(line) * font * 1.35f;
        x += width + font * (it.series ? 0.8f : 0.6f);
    }
    return items;
}

} // namespace

ScreenRect drawPlot(const char* id, const PlotOptions& o, const std::vector<PlotSeries>& series,
                    const std::vector<double>& markers) {
    const float font = ImGui::GetFontSize();
    ImVec2 size = ImGui::GetContentRegionAvail();
    if (o.height > 0.0f) size.y = o.height;
    size.x = std::max(size.x, font * 8.0f);
    // Evidence big enough to see from the back row: at least 13% of the display's height (140 px
    // at 1080p; the window scrolls if it has less room).
    size.y = std::max(
        {size.y, font * 5.0f, static_cast<float>(kMinPlotShare) * ImGui::GetIO().DisplaySize.y});
    ImGui::InvisibleButton(id, size);
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 outerMin = ImGui::GetItemRectMin();
    const ImVec2 outerMax = ImGui::GetItemRectMax();
    ImDrawList* dl = ImGui::GetWindowDrawList();

    // Data ranges (in axis units: log10 where log).
    double x0 = axisValue(o.x.lo, o.logX), x1 = axisValue(o.x.hi, o.logX);
    double ylo = INFINITY, yhi = -INFINITY, xlo = INFINITY, xhi = -INFINITY;
    for (const PlotSeries& s : series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t i = 0; i < n; ++i) {
            const double x = axisValue(s.x[i], o.logX), y = axisValue(s.y[i], o.logY);
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            xlo = std::min(xlo, x);
            xhi = std::max(xhi, x);
            if (!o.autoX && (x < x0 || x > x1)) continue;
            ylo = std::min(ylo, y);
            yhi = std::max(yhi, y);
        }
    }
    if (o.autoX && xlo <= xhi) {
        const PlotRange r = paddedRange(xlo, xhi, 0.05);
        x0 = r.lo;
        x1 = r.hi;
    }
    if (!(x1 > x0)) x1 = x0 + 1.0;
    if (o.includeZero && !o.logY) {
        ylo = std::min(ylo, 0.0);
        yhi = std::max(yhi, 0.0);
    }
    if (!(ylo <= yhi)) ylo = yhi = 0.0;
    const PlotRange yr = paddedRange(ylo, yhi, 0.1);

    // Line thickness: a whole number of pixels, so ImGui draws each segment as two triangles
    // textured from the atlas's baked anti-aliased lines, instead of six with a geometric fringe.
    const float thickness = std::max(1.0f, std::round(font * 0.12f));
    // Layout: title, unit and legend above the plot area (wrapped onto more lines when they do
    // not fit), y labels on the left, x labels below.
    const std::vector<HeaderItem> items =
        layoutHeader(o, series, outerMin.x + font * 0.2f, outerMax.x, outerMin.y + font * 0.1f);
    const float header = (items.empty() ? 1.0f : float(items.back().line + 1)) * font * 1.35f;
    const int yMaxTicks = std::max(2, int((size.y - header - font * 1.5f) / (font * 1.8f)));
    const int yMinTicks = o.logY ? 1 : kMinYTicks;
    std::vector<double> yTicks = ticksFor(yr.lo, yr.hi, o.logY, yMinTicks, yMaxTicks);
    // Ticks closer than a line of text (kMinYTicks on a short plot): the least step of 1, 2, 2.5
    // or 5 times a power of ten whose numbers do not touch, where it still numbers kMinYTicks
    // (a 154 px plot at UI 1.5: -2.5, 0, 2.5 rather than -4, -2, 0, 2 18 px apart); else
    // labelStride below numbers every second or third tick.
    double yStep = NAN; // the step whose digits the numbers have (tickLabel)
    const float areaH = (outerMax.y - font * 1.4f) - (outerMin.y + header);
    if (!o.logY && yTicks.size() >= 2 && areaH > 0.0f) {
        const double perUnit = areaH / (yr.hi - yr.lo);
        const double least = (ImGui::GetTextLineHeight() + font * 0.1f) / perUnit;
        if ((yTicks[1] - yTicks[0]) < least) {
            const double power = std::pow(10.0, std::floor(std::log10(least)));
            for (const double mantissa : {1.0, 2.0, 2.5, 5.0, 10.0}) {
                if (mantissa * power < least) continue;
                const std::vector<double> wider = ticksEvery(yr.lo, yr.hi, mantissa * power);
                if (static_cast<int>(wider.size()) >= kMinYTicks) {
                    yTicks = wider;
                    // The digits of its numbers: 2.5 needs one more than its power ("2.5", not
                    // "2"; "25" and "0.25" as they are).
                    yStep = mantissa == 2.5 ? 0.1 * mantissa * power : mantissa * power;
                }
                break;
            }
        }
    }
    float labelW = ImGui::CalcTextSize("0").x;
    std::vector<std::string> yLabels;
    for (double t : yTicks) {
        yLabels.push_back(std::isfinite(yStep)
                              ? tickLabel(t, yStep)
                              : labelFor(t, yr.lo, yr.hi, o.logY, yMinTicks, yMaxTicks));
        labelW = std::max(labelW, ImGui::CalcTextSize(yLabels.back().c_str()).x);
    }
    Mapping m{x0,
              x1,
              yr.lo,
              yr.hi,
              ImVec2(outerMin.x + labelW + font * 0.6f, outerMin.y + header),
              ImVec2(outerMax.x - font * 0.5f, outerMax.y - font * 1.4f)};
    const ScreenRect widget{outerMin.x, outerMin.y, outerMax.x - outerMin.x,
                            outerMax.y - outerMin.y};
    if (m.max.x - m.min.x < 10.0f || m.max.y - m.min.y < 10.0f) return widget;
    dl->AddRectFilled(m.min, m.max, frameBg(), 3.0f);

    // Grid and tick labels: every tick's line, and its number where the numbers do not touch
    // (issue 39: a short plot at a large UI scale has room for fewer labels than kMinYTicks).
    const std::size_t stride = labelStride(yTicks, m, ImGui::GetTextLineHeight() + font * 0.1f);
    const std::size_t first = firstLabelled(yTicks, stride);
    const int xMaxTicks = std::max(2, int((m.max.x - m.min.x) / (font * 4.5f)));
    const std::vector<double> xTicks = ticksFor(x0, x1, o.logX, 1, xMaxTicks);
    const float xRow = m.max.y + font * 0.15f; // the x axis's numbers' top
    // A y number reaching down into the x numbers' row (the bottom tick's, -1 on step 10's
    // momentum plot): the x axis's first number starts right of it rather than on it.
    float firstXFrom = -INFINITY;
    for (std::size_t i = 0; i < yTicks.size(); ++i) {
        const float y = m.sy(yTicks[i]);
        dl->AddLine(ImVec2(m.min.x, y), ImVec2(m.max.x, y),
                    yTicks[i] == 0.0 && !o.logY ? zeroColor() : gridColor());
        if (i < first || (i - first) % stride != 0) continue;
        const ImVec2 ts = ImGui::CalcTextSize(yLabels[i].c_str());
        const float right = m.min.x - font * 0.3f;
        if (y + ts.y * 0.5f > xRow + 1.0f) firstXFrom = right + font * 0.2f;
        dl->AddText(ImVec2(right - ts.x, y - ts.y * 0.5f), axisText(), yLabels[i].c_str());
    }
    for (std::size_t i = 0; i < xTicks.size(); ++i) {
        const float x = m.sx(xTicks[i]);
        dl->AddLine(ImVec2(x, m.min.y), ImVec2(x, m.max.y), gridColor());
        std::string text = labelFor(xTicks[i], x0, x1, o.logX, 1, xMaxTicks);
        if (i + 1 == xTicks.size() && *o.xUnit) text += std::string(" ") + o.xUnit;
        const ImVec2 ts = ImGui::CalcTextSize(text.c_str());
        float tx = x - ts.x * 0.5f;
        if (i == 0) tx = std::max(tx, firstXFrom);
        tx = std::min(tx, outerMax.x - ts.x);
        dl->AddText(ImVec2(tx, xRow), axisText(), text.c_str());
    }

    dl->PushClipRect(m.min, m.max, true);
    // Collision markers.
    // At most one marker per 3 px column, each a 1 px rectangle (two triangles, no anti-aliased
    // fringe): a gas has hundreds of collisions per second, and overdrawn translucent lines are
    // what costs on a software rasteriser.
    std::size_t drawn = 0;
    float lastColumn = -1e9f;
    for (auto it = markers.rbegin(); it != markers.rend() && drawn < kMaxMarkers; ++it) {
        const double x = axisValue(*it, o.logX);
        if (!(x >= x0 && x <= x1)) continue;
        const float sx = std::floor(m.sx(x) / 3.0f) * 3.0f;
        if (sx == lastColumn) continue;
        lastColumn = sx;
        dl->AddRectFilled(ImVec2(sx, m.min.y), ImVec2(sx + 1.0f, m.max.y), markerColor());
        ++drawn;
    }
    // Series: the bands first, under the lines.
    std::vector<const PlotSeries*> order;
    for (const PlotSeries& s : series)
        if (s.band) order.push_back(&s);
    for (const PlotSeries& s : series)
        if (!s.band) order.push_back(&s);
    std::vector<ImVec2> mapped, pts;
    std::vector<float> xs, ys;
    for (const PlotSeries* sp : order) {
        const PlotSeries& s = *sp;
        mapped.clear();
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t i = 0; i < n; ++i) {
            const double x = axisValue(s.x[i], o.logX), y = axisValue(s.y[i], o.logY);
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            mapped.emplace_back(m.sx(x), m.sy(y));
        }
        if (s.points) {
            pts = mapped;
        } else {
            xs.clear();
            ys.clear();
            for (const ImVec2& p : mapped) {
                xs.push_back(p.x);
                ys.push_back(p.y);
            }
            pts.clear();
            for (std::size_t k : columnExtremes(xs, ys, kColumnPx)) pts.push_back(mapped[k]);
        }
        if (pts.size() >= 2)
            polyline(dl, pts, s.band ? bandColor(s.color) : s.color, s.dash,
                     s.band ? thickness * kBandWidth : thickness);
        if (s.points) {
            for (const ImVec2& p : pts) dl->AddCircleFilled(p, thickness * 1.8f, s.color, 8);
        }
    }
    // The timeline's "now": where the scrubbed time is in the recorded run.
    if (std::isfinite(o.cursor)) {
        const double x = axisValue(o.cursor, o.logX);
        if (x >= x0 && x <= x1) {
            const float sx = std::round(m.sx(x));
            dl->AddRectFilled(ImVec2(sx - 1.0f, m.min.y), ImVec2(sx + 1.0f, m.max.y),
                              cursorColor());
            dl->AddText(ImVec2(sx + font * 0.25f, m.max.y - font * 1.1f), cursorColor(), "now");
        }
    }
    dl->PopClipRect();

    // Title, unit and legend.
    for (const HeaderItem& it : items) {
        if (it.series) {
            const float cy = it.y + font * 0.5f;
            const PlotSeries& ps = *it.series;
            polyline(dl, {ImVec2(it.x, cy), ImVec2(it.x + font * 0.9f, cy)},
                     ps.band ? bandColor(ps.color) : ps.color, ps.dash,
                     thickness * (ps.band ? kBandWidth : 1.5f));
            dl->AddText(ImVec2(it.x + font * 1.2f, it.y), uiThemed(IM_COL32(225, 230, 240, 255)),
                        it.text.c_str());
        } else {
            dl->AddText(ImVec2(it.x, it.y), it.color, it.text.c_str());
        }
    }

    // Values under the cursor.
    if (hovered) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        if (mouse.x >= m.min.x && mouse.x <= m.max.x) {
            dl->AddLine(ImVec2(mouse.x, m.min.y), ImVec2(mouse.x, m.max.y),
                        uiThemed(IM_COL32(255, 255, 255, 90)));
            const double x = x0 + (mouse.x - m.min.x) / (m.max.x - m.min.x) * (x1 - x0);
            ImGui::BeginTooltip();
            ImGui::Text("x = %.4g %s", o.logX ? std::pow(10.0, x) : x, o.xUnit);
            for (const PlotSeries& s : series) {
                // Nearest sample by x.
                double best = INFINITY, value = NAN;
                const std::size_t n = std::min(s.x.size(), s.y.size());
                for (std::size_t i = 0; i < n; ++i) {
                    const double d = std::abs(axisValue(s.x[i], o.logX) - x);
                    if (d < best) {
                        best = d;
                        value = s.y[i];
                    }
                }
                if (std::isfinite(value)) {
                    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(s.color), "%s = %.4g %s",
                                       s.label.c_str(), value, o.yUnit);
                }
            }
            ImGui::EndTooltip();
        }
    }
    return widget;
}
