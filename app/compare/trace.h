// A student's trace: what their own engine printed each frame (issue 29, "Check your own
// engine"), read from CSV into the sandbox's units. The columns are those `sandbox-cli run
// --trace` writes: `t` (or `frame`), then NAME_x, NAME_y, NAME_vx, NAME_vy per block, the blocks
// matched to the scene's by name (NAME x and NAME.x too; other columns are ignored). A header
// row; comma, semicolon or tab between fields; a decimal point, or a decimal comma as a European
// spreadsheet writes it (with semicolons or tabs, or in quotes).
//
// Units: SI (m, m/s, y up) or gxp, the course engine's: pixels with y down, velocities in pixels
// per frame at the scene's frame rate, the world's top-left corner at pixel (0, 0) or at the
// origin given (a student's walls are usually a margin inside the window).
//
// Every refusal names its place: "trace.csv:5:23: column 'm1_x': 'abc' is not a number". The
// reader streams lines of at most kMaxTraceLineBytes and keeps at most kMaxTraceValues numbers,
// so no file can take unbounded memory or time.
#pragma once

#include "scene.h"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

// The longest line read (a header of 10 MB of columns is refused at its first MiB).
inline constexpr std::size_t kMaxTraceLineBytes = 1 << 20;
// The most numbers kept (frames x traced blocks x 4): 80 MB of doubles.
inline constexpr std::size_t kMaxTraceValues = 10'000'000;

enum class TraceUnits { Si, Gxp };

// How a trace's numbers map to the sandbox's: SI as is, or gxp pixels.
struct TraceUnitsSpec {
    TraceUnits units = TraceUnits::Si;
    double pxPerM = 0.0; // gxp: pixels per metre
    Vec2 originPx;       // gxp: the pixel where the world's top-left corner is
};

// "si" | "gxp"; false (and `units` left alone) for anything else.
bool parseTraceUnits(const std::string& name, TraceUnits& units);
// The gxp flags' values, as sandbox-cli compare and the app's --compare read them: "" when good
// (stored), otherwise what they must be. Pixels per metre from 1e-6 to 1e9; the origin "X,Y".
std::string parsePxPerM(const std::string& text, double& pxPerM);
std::string parsePxOrigin(const std::string& text, Vec2& origin);

// ---- The trace's units on a command line: one table and one rule for both parsers ----
// sandbox-cli compare (its units' flag --units) and sandbox / sandbox-offscreen beside --compare
// (--trace-units) share these options: their words here, their reading in readTraceUnitsOptions.
struct OptionWords {
    const char* flag;
    const char* value; // the value's name in the help
    const char* help;
};
inline constexpr OptionWords kTraceUnitsOption{
    "", "si|gxp",
    "The trace's units: si (m, m/s, y up; the default) or gxp (pixels, y down, velocities in "
    "pixels per frame; needs --px-per-m)"};
inline constexpr OptionWords kPxPerMOption{"--px-per-m", "N",
                                           "gxp: pixels per metre (required with gxp)"};
inline constexpr OptionWords kPxOriginOption{
    "--px-origin", "X,Y", "gxp: the pixel X,Y of the world's top-left corner (default 0,0)"};

// The options as given (absent: not given).
struct TraceUnitsOptions {
    std::optional<std::string> units, pxPerM, pxOrigin;
};
// Why they are refused: the flag, the text given ("" when the refusal is of the combination) and
// what it must be; `usage` when bad usage (exit 2: an unknown unit, gxp without its scale, a
// scale without gxp) rather than a bad value (a scale or an origin out of its limits).
struct TraceUnitsRefusal {
    std::string flag;
    std::string text;
    std::string expected;
    bool usage = false;
};
// Reads the options into `spec` (`unitsFlag` names the units' own flag in a refusal): gxp needs
// --px-per-m; --px-per-m and --px-origin are for gxp only; the values as parsePxPerM and
// parsePxOrigin read them. Nothing when they are good.
std::optional<TraceUnitsRefusal> readTraceUnitsOptions(const TraceUnitsOptions& given,
                                                       const char* unitsFlag, TraceUnitsSpec& spec);

// One row: the state of each traced block after `frame` frames (frame 0: the start).
struct TraceRow {
    std::int64_t frame = 0;
    int line = 0;               // line of the file, for messages
    std::vector<Vec2> position; // m, per traced block (Trace::blocks' order)
    std::vector<Vec2> velocity; // m/s
};

struct Trace {
    std::string source;         // the file's name, for messages
    std::vector<int> blocks;    // scene indices of the traced blocks
    std::vector<TraceRow> rows; // frames strictly increasing
    TraceUnitsSpec units;
    std::vector<std::string> notes; // what the reader took as given (ignored columns, ...)
};

struct TraceResult {
    std::optional<Trace> trace;
    // Meaningful only when !trace: `where` names the place ("trace.csv:5:23" or "trace.csv:1"),
    // `message` says what is wrong, naming the column.
    SceneError error;
};

// Reads a trace of `scene` (its blocks' names, its bounds, the frame length `dt` of the
// settings compared with) from `in`; `source` names it in messages.
TraceResult readTrace(std::istream& in, const std::string& source, const Scene& scene, double dt,
                      const TraceUnitsSpec& units);
TraceResult loadTraceFile(const std::string& path, const Scene& scene, double dt,
                          const TraceUnitsSpec& units);

// The name a trace's columns give block `index` of `scene` (its name, or "blocks[i]").
std::string traceBlockName(const Scene& scene, int index);

// A state in SI units as the gxp numbers a student's engine prints (and back): pixels with y
// down from the world's top-left corner at `units.originPx`, velocities in pixels per frame.
Vec2 positionToPixels(Vec2 metres, const Bounds& bounds, const TraceUnitsSpec& units);
Vec2 positionFromPixels(Vec2 px, const Bounds& bounds, const TraceUnitsSpec& units);
Vec2 velocityFromPixels(Vec2 pxPerFrame, double dt, const TraceUnitsSpec& units);
