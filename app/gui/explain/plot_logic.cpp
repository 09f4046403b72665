#include "plot_logic.h"

#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

double niceTickStep(double span, int maxTicks) {
    if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
    const int parts = std::max(1, maxTicks);
    const double raw = span / parts;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * power >= raw * (1.0 - 1e-9)) return m * power;
    }
    return 10.0 * power;
}

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
    return ticksEvery(lo, hi, niceTickStep(hi - lo, maxTicks));
}

double axisTickStep(double lo, double hi, int minTicks, int maxTicks) {
    double step = niceTickStep(hi - lo, maxTicks);
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return step;
    for (int notch = 0; notch < 12 && static_cast<int>(ticksEvery(lo, hi, step).size()) < minTicks;
         ++notch) {
        const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        const double mantissa = step / power; // 1, 2 or 5
        step = mantissa > 4.0 ? 2.0 * power : mantissa > 1.5 ? power : 0.5 * power;
    }
    return step;
}

std::vector<double> ticksEvery(double lo, double hi, double step) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || !(step > 0.0)) return ticks;
    const double first = std::ceil(lo / step - 1e-9);
    for (double k = first; k * step <= hi + step * 1e-9 && ticks.size() < 64; k += 1.0) {
        double v = k * step;
        if (std::abs(v) < step * 1e-9) v = 0.0;
        ticks.push_back(v);
    }
    return ticks;
}

std::vector<double> decadeTicks(double logLo, double logHi, int maxTicks) {
    std::vector<double> ticks;
    if (!(logHi > logLo)) return ticks;
    if (std::floor(logHi) - std::ceil(logLo) < 1.0) return niceTicks(logLo, logHi, maxTicks);
    const double span = std::floor(logHi) - std::ceil(logLo);
    const double every = std::max(1.0, std::ceil(span / std::max(1, maxTicks)));
    for (double e = std::ceil(logLo); e <= logHi + 1e-9; e += every) ticks.push_back(e);
    return ticks;
}

std::string tickLabel(double value, double step) {
    int decimals = 0;
    if (step > 0.0 && step < 1.0) {
        decimals = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
        decimals = std::min(decimals, 6);
    }
    if (std::abs(value) < step * 1e-6) value = 0.0;
    char text[48];
    if (std::abs(value) >= 1e6) {
        number_text::printGeneral(text, sizeof text, value, 3); // "%.3g"
    } else {
        number_text::printFixed(text, sizeof text, value, decimals); // "%.*f"
    }
    return text;
}

std::string decadeLabel(double exponent) {
    const double value = std::pow(10.0, exponent);
    char text[48];
    if (exponent >= -3.0 && exponent <= 4.0 && std::abs(exponent - std::round(exponent)) < 1e-9) {
        std::snprintf(text, sizeof text, "%g", value);
    } else {
        std::snprintf(text, sizeof text, "%.0e", value);
    }
    return text;
}

PlotRange scrollingWindow(double now, double span) {
    if (!(span > 0.0)) span = 1.0;
    if (!(now > span)) return {0.0, span};
    return {now - span, now};
}

PlotRange timelineWindow(double now, double newest, double span) {
    if (!(span > 0.0)) span = 1.0;
    const double end = newest > now ? std::min(newest, now + 0.5 * span) : now;
    return scrollingWindow(end, span);
}

PlotRange paddedRange(double lo, double hi, double margin) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return {-1.0, 1.0};
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
        const double half = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
        return {lo - half, hi + half};
    }
    const double pad = (hi - lo) * margin;
    return {lo - pad, hi + pad};
}

TimeSeries::TimeSeries(int channels, std::size_t capacity)
    : channels_(std::max(1, channels)), capacity_(std::max<std::size_t>(2, capacity)),
      times_(capacity_), values_(capacity_ * static_cast<std::size_t>(channels_)) {}

std::size_t TimeSeries::slot(std::size_t i) const {
    return (head_ + i) % capacity_;
}

void TimeSeries::push(double t, const double* values) {
    std::size_t s;
    if (size_ < capacity_) {
        s = slot(size_);
        ++size_;
    } else {
        s = head_;
        head_ = (head_ + 1) % capacity_;
    }
    times_[s] = t;
    for (int c = 0; c < channels_; ++c) {
        values_[s * static_cast<std::size_t>(channels_) + static_cast<std::size_t>(c)] = values[c];
    }
}

void TimeSeries::truncateAfter(double t) {
    while (size_ > 0 && time(size_ - 1) > t) --size_;
}

double TimeSeries::time(std::size_t i) const {
    return i < size_ ? times_[slot(i)] : 0.0;
}

double TimeSeries::value(std::size_t i, int channel) const {
    if (i >= size_ || channel < 0 || channel >= channels_) return 0.0;
    return values_[slot(i) * static_cast<std::size_t>(channels_) +
                   static_cast<std::size_t>(channel)];
}

std::size_t TimeSeries::firstAtOrAfter(double t) const {
    std::size_t lo = 0, hi = size_;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (time(mid) < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::vector<std::size_t> columnExtremes(const std::vector<float>& xs, const std::vector<float>& ys,
                                        float columnPx) {
    std::vector<std::size_t> kept;
    const std::size_t n = std::min(xs.size(), ys.size());
    std::size_t i = 0;
    while (i < n) {
        const float column = std::floor(xs[i] / columnPx);
        std::size_t high = i, low = i, j = i;
        for (; j < n && std::floor(xs[j] / columnPx) == column; ++j) {
            if (ys[j] > ys[high]) high = j;
            if (ys[j] < ys[low]) low = j;
        }
        kept.push_back(std::min(high, low));
        if (high != low) kept.push_back(std::max(high, low));
        if (j == n && kept.back() != n - 1) kept.push_back(n - 1);
        i = j;
    }
    return kept;
}

std::vector<std::vector<PlotPoint>> dashPieces(const std::vector<PlotPoint>& line, Dash dash,
                                               float unit) {
    if (dash == Dash::Solid || line.size() < 2 || !(unit > 0.0f)) return {line};
    const float on = dash == Dash::Dashed ? 3.0f * unit : unit;
    const float off = dash == Dash::Dashed ? 2.0f * unit : 1.5f * unit;
    std::vector<std::vector<PlotPoint>> pieces;
    bool drawing = true;
    float left = on; // px until the pattern switches
    std::vector<PlotPoint> piece{line[0]};
    for (std::size_t i = 1; i < line.size(); ++i) {
        PlotPoint from = line[i - 1];
        const PlotPoint to = line[i];
        float length = std::hypot(to.x - from.x, to.y - from.y);
        while (length > left) {
            const float t = left / length;
            const PlotPoint at{from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
            if (drawing) {
                piece.push_back(at);
                pieces.push_back(piece);
                piece.clear();
            } else {
                piece = {at};
            }
            drawing = !drawing;
            length -= left;
            from = at;
            left = drawing ? on : off;
        }
        left -= length;
        if (drawing) piece.push_back(to);
    }
    if (drawing && piece.size() >= 2) pieces.push_back(piece);
    return pieces;
}
