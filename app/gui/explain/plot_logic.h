// The plot widget's pure logic: "nice" tick values (1-2-5 steps, decades on log axes), the
// scrolling time window, padded value ranges, tick labels, and a fixed-capacity time series.
// No ImGui here, so it is tested on its own; plot_widget.cpp draws with it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

struct PlotRange {
    double lo = 0.0;
    double hi = 1.0;
};

// A step of 1, 2 or 5 times a power of ten that splits `span` into at most `maxTicks` parts.
double niceTickStep(double span, int maxTicks);
// The multiples of niceTickStep(hi - lo, maxTicks) within [lo, hi] (ends included).
std::vector<double> niceTicks(double lo, double hi, int maxTicks);
// The multiples of `step` within [lo, hi] (ends included).
std::vector<double> ticksEvery(double lo, double hi, double step);
// The step of an axis over [lo, hi] that labels at least `minTicks` values and, where it can, at
// most `maxTicks` parts: niceTickStep, made one 1-2-5 notch smaller (10 -> 5 -> 2 -> 1) until
// `minTicks` multiples of it lie within [lo, hi] (a plot's y axis labels three values or more,
// not just "0").
double axisTickStep(double lo, double hi, int minTicks, int maxTicks);
// Powers of ten within [10^lo, 10^hi], as exponents (lo and hi are log10 values); when the range
// holds fewer than two decades, niceTicks of the exponents instead.
std::vector<double> decadeTicks(double logLo, double logHi, int maxTicks);
// The label of a tick at `value` on an axis whose ticks are `step` apart: just enough decimals.
std::string tickLabel(double value, double step);
// The label of a decade tick: "1", "10", "0.01", "1e+05".
std::string decadeLabel(double exponent);
// The last `span` seconds before `now`, or [0, span] while now < span.
PlotRange scrollingWindow(double now, double span);
// The plots' window at `now` when the recording reaches `newest`: the scrolling window while
// live (newest <= now); while the timeline replays an earlier time, moved on so that `now` sits
// in the middle of it as far as the recorded future allows (at most span/2 after now).
PlotRange timelineWindow(double now, double newest, double span);
// [lo, hi] widened by `margin` of its span on both sides; a flat range becomes +-1 around it
// (or +-10% of its value), so a constant series still shows as a line in the middle.
PlotRange paddedRange(double lo, double hi, double margin = 0.08);

// The points a long line keeps (indices into xs/ys, increasing): per run of consecutive points in
// the same column of `columnPx` (by x), the highest and the lowest, in the order they come, and the
// series' last point. The line looks the same (every spike stays) with at most about two points
// per column; a software rasteriser pays for each segment, however short.
std::vector<std::size_t> columnExtremes(const std::vector<float>& xs, const std::vector<float>& ys,
                                        float columnPx);

// How a plot series' line is drawn, besides its colour: a second cue for telling series apart.
enum class Dash { Solid, Dashed, Dotted };
struct PlotPoint {
    float x, y;
};
// The pieces of `line` (px) that a dash pattern draws: Solid the whole line; Dashed `unit`*3
// drawn and `unit`*2 left out, Dotted `unit` drawn and `unit`*1.5 left out, measured along the
// line (the pattern runs on across its corners). Each piece is a polyline of its own.
std::vector<std::vector<PlotPoint>> dashPieces(const std::vector<PlotPoint>& line, Dash dash,
                                               float unit);

// Samples (t, v[0..k)) in a ring buffer of `capacity`; the oldest are dropped.
class TimeSeries {
  public:
    explicit TimeSeries(int channels = 1, std::size_t capacity = 3600);
    void push(double t, const double* values);
    void clear() {
        size_ = 0;
        head_ = 0;
    }
    // Drops the samples later than `t` (the timeline went back).
    void truncateAfter(double t);
    std::size_t size() const { return size_; }
    std::size_t bytes() const { return (times_.capacity() + values_.capacity()) * sizeof(double); }
    int channels() const { return channels_; }
    // Sample `i`: 0 is the oldest.
    double time(std::size_t i) const;
    double value(std::size_t i, int channel) const;
    // Index of the first sample at or after `t` (size() when none).
    std::size_t firstAtOrAfter(double t) const;

  private:
    std::size_t slot(std::size_t i) const;
    int channels_;
    std::size_t capacity_;
    std::size_t size_ = 0;
    std::size_t head_ = 0; // slot of the oldest sample
    std::vector<double> times_;
    std::vector<double> values_; // capacity_ * channels_
};
