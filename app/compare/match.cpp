#include "match.h"

#include "input_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

// `value` to 3 significant digits, so the tolerance printed is the tolerance used.
double threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return std::strtod(text, nullptr);
}

} // namespace

Tolerance traceTolerance(const Scene& scene, double dt, double position) {
    Tolerance t;
    if (position > 0.0) {
        t.position = position;
        t.why = "as given";
    } else {
        double smallest = 1.0;
        bool any = false;
        for (const BlockDef& b : scene.blocks) {
            const double s = std::min(b.size.x, b.size.y);
            smallest = any ? std::min(smallest, s) : s;
            any = true;
        }
        t.position = threeDigits(smallest / 1000.0);
        t.why = "a thousandth of the smallest block (" + limits::formatNumber(smallest) +
                " m): float rounding in a single-precision engine stays near 1e-4 m over a few "
                "hundred frames, a real difference is a fraction of a block";
    }
    t.velocity = threeDigits(t.position / dt);
    t.why += "; velocities: the speed that covers that distance in one frame";
    return t;
}

double Difference::by() const {
    return std::abs(yours - reference);
}

const Difference& RunMatch::first() const {
    if (!velocity.found()) return position;
    if (!position.found()) return velocity;
    return velocity.frame < position.frame ? velocity : position;
}

namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    return (h ^ v) * 1099511628211ull;
}

} // namespace

RunMatch matchRun(const Scene& scene, const WorldSettings& settings, const Trace& trace,
                  const Tolerance& tolerance) {
    Scene s = scene;
    s.settings = settings;
    World world = makeWorld(s);
    world.settings.measureTime = false; // no step's time is shown (in the browser: two JS calls)
    RunMatch m;
    m.hash = 14695981039346656037ull;
    std::vector<Block> before = world.blocks;
    auto compareRow = [&](const TraceRow& row) {
        for (std::size_t b = 0; b < trace.blocks.size(); ++b) {
            const int index = trace.blocks[b];
            const Block& ref = world.blocks[static_cast<std::size_t>(index)];
            for (int axis = 0; axis < 2; ++axis) {
                Difference d;
                d.frame = row.frame;
                d.block = index;
                d.axis = axis;
                d.line = row.line;
                d.yours = row.position[b][axis];
                d.reference = ref.position[axis];
                const double dp = d.by();
                m.maxPositionError = std::max(m.maxPositionError, dp);
                const bool positionAgrees = dp <= tolerance.position;
                if (!positionAgrees && !m.position.found()) m.position = d;
                d.velocity = true;
                d.yours = row.velocity[b][axis];
                d.reference = ref.velocity[axis];
                const double dv = d.by();
                m.maxVelocityError = std::max(m.maxVelocityError, dv);
                if (dv <= tolerance.velocity) continue;
                // At rest in the simulation over this frame, and where the trace says: a
                // velocity the position never shows.
                const double moved = std::abs(
                    ref.position[axis] - before[static_cast<std::size_t>(index)].position[axis]);
                const bool resting = moved <= 0.01 * tolerance.position && positionAgrees;
                Difference& slot = resting ? m.resting : m.velocity;
                if (!slot.found()) slot = d;
            }
        }
    };
    std::size_t next = 0;
    if (!trace.rows.empty() && trace.rows.front().frame == 0) compareRow(trace.rows[next++]);
    const std::int64_t last = trace.rows.empty() ? 0 : trace.rows.back().frame;
    for (std::int64_t frame = 1; frame <= last; ++frame) {
        before = world.blocks;
        world.step();
        m.hash = mix(m.hash, stateHash(world));
        if (next < trace.rows.size() && trace.rows[next].frame == frame)
            compareRow(trace.rows[next++]);
    }
    m.lastFrame = last;
    return m;
}
