#include "trace.h"

#include "input_limits.h"
#include "printable.h"
#include "scene_json.h"
#include "text_format.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <string_view>

namespace {

// ---- Lines and fields ----

// Reads one line (without its "\n" or "\r\n") of at most kMaxTraceLineBytes; false at the end.
// `tooLong` is set when the line goes on beyond the limit (the rest is not read).
bool readLine(std::istream& in, std::string& line, bool& tooLong) {
    line.clear();
    tooLong = false;
    std::streambuf* buf = in.rdbuf();
    bool any = false;
    for (;;) {
        const int c = buf->sbumpc();
        if (c == std::char_traits<char>::eof()) break;
        any = true;
        if (c == '\n') break;
        if (line.size() >= kMaxTraceLineBytes) {
            tooLong = true;
            return true;
        }
        line.push_back(static_cast<char>(c));
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return any;
}

struct Field {
    std::size_t begin = 0, end = 0; // bytes of the line, quotes excluded
    bool quoted = false;
    std::size_t column = 1; // 1-based byte column of the field's first byte, for messages
};

// Splits a line at `separator` outside double quotes; false (with the column) on an unclosed
// quote. Fields are trimmed of spaces.
bool splitFields(const std::string& line, char separator, std::vector<Field>& fields,
                 std::size_t& badColumn) {
    fields.clear();
    std::size_t i = 0;
    for (;;) {
        Field f;
        while (i < line.size() && (line[i] == ' ')) ++i;
        f.column = i + 1;
        if (i < line.size() && line[i] == '"') {
            f.quoted = true;
            f.begin = ++i;
            for (;;) {
                if (i >= line.size()) {
                    badColumn = f.column;
                    return false;
                }
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        i += 2;
                        continue;
                    }
                    break;
                }
                ++i;
            }
            f.end = i++;
            while (i < line.size() && line[i] == ' ') ++i;
        } else {
            f.begin = i;
            while (i < line.size() && line[i] != separator) ++i;
            f.end = i;
            while (f.end > f.begin && line[f.end - 1] == ' ') --f.end;
        }
        fields.push_back(f);
        if (i >= line.size()) return true;
        if (line[i] != separator) { // text after a closing quote
            badColumn = i + 1;
            return false;
        }
        ++i;
    }
}

std::string fieldText(const std::string& line, const Field& f) {
    std::string text = line.substr(f.begin, f.end - f.begin);
    if (f.quoted) { // "" inside quotes is one "
        std::string out;
        for (std::size_t i = 0; i < text.size(); ++i) {
            out.push_back(text[i]);
            if (text[i] == '"' && i + 1 < text.size() && text[i + 1] == '"') ++i;
        }
        return out;
    }
    return text;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The separator of the header: a semicolon or a tab outside quotes wins over commas (a European
// spreadsheet writes "1,5;2,25").
char separatorOf(const std::string& header) {
    bool quoted = false, comma = false, tab = false;
    for (char c : header) {
        if (c == '"') quoted = !quoted;
        if (quoted) continue;
        if (c == ';') return ';';
        tab |= c == '\t';
        comma |= c == ',';
    }
    return tab ? '\t' : comma ? ',' : ';';
}

const char* separatorName(char separator) {
    return separator == ';' ? "semicolons" : separator == '\t' ? "tabs" : "commas";
}

// ---- Columns ----

enum class TimeColumn { Seconds, Frame };

// What the header's time column is: "t", "time" (seconds; "t (s)" too) or "frame".
std::optional<TimeColumn> timeColumnOf(std::string name) {
    name = lower(name);
    if (const std::size_t paren = name.find('('); paren != std::string::npos) {
        name.resize(paren);
        while (!name.empty() && name.back() == ' ') name.pop_back();
    }
    if (name == "t" || name == "time") return TimeColumn::Seconds;
    if (name == "frame") return TimeColumn::Frame;
    return std::nullopt;
}

constexpr const char* kComponents[] = {"x", "y", "vx", "vy"};

// A header name split into a block name and a component: "m1 = 1 kg_vx" -> ("m1 = 1 kg", 2).
bool splitColumnName(const std::string& name, std::string& block, int& component) {
    const std::size_t sep = name.find_last_of(" _.");
    if (sep == std::string::npos || sep == 0) return false;
    const std::string c = lower(name.substr(sep + 1));
    for (int k = 0; k < 4; ++k)
        if (c == kComponents[k]) {
            block = name.substr(0, sep);
            while (!block.empty() && block.back() == ' ') block.pop_back();
            component = k;
            return !block.empty();
        }
    return false;
}

std::string inQuotes(const std::string& text) {
    return "'" + printable(text) + "'";
}

// A number in a cell; "" on success, otherwise why not.
std::string parseCell(std::string text, bool decimalComma, double& value) {
    if (text.empty()) return "empty";
    if (decimalComma) std::replace(text.begin(), text.end(), ',', '.');
    if (!limits::parseNumber(text, value)) {
        const std::string l = lower(text);
        if (l.find("nan") != std::string::npos)
            return inQuotes(text) + " is not a number (NaN: the engine's arithmetic broke down at "
                                    "this frame or before)";
        if (l.find("inf") != std::string::npos) return inQuotes(text) + " is not a finite number";
        return inQuotes(text) + " is not a number";
    }
    if (!std::isfinite(value)) return inQuotes(text) + " is too large";
    return "";
}

} // namespace

bool parseTraceUnits(const std::string& name, TraceUnits& units) {
    if (name == "si")
        units = TraceUnits::Si;
    else if (name == "gxp")
        units = TraceUnits::Gxp;
    else
        return false;
    return true;
}

std::string parsePxPerM(const std::string& text, double& pxPerM) {
    static constexpr limits::Range kPxPerM{1e-6, 1e9, "px/m"};
    return limits::textViolation(text, kPxPerM, pxPerM);
}

std::optional<TraceUnitsRefusal>
readTraceUnitsOptions(const TraceUnitsOptions& given, const char* unitsFlag, TraceUnitsSpec& spec) {
    TraceUnitsSpec read;
    if (given.units && !parseTraceUnits(*given.units, read.units))
        return TraceUnitsRefusal{unitsFlag, *given.units, "must be si or gxp", true};
    const bool gxp = read.units == TraceUnits::Gxp;
    if (gxp && !given.pxPerM)
        return TraceUnitsRefusal{std::string(unitsFlag) + " gxp", "",
                                 "needs --px-per-m N (pixels per metre)", true};
    if (!gxp && (given.pxPerM || given.pxOrigin))
        return TraceUnitsRefusal{"--px-per-m and --px-origin", "",
                                 std::string("are for ") + unitsFlag + " gxp", true};
    if (given.pxPerM)
        if (std::string p = parsePxPerM(*given.pxPerM, read.pxPerM); !p.empty())
            return TraceUnitsRefusal{kPxPerMOption.flag, *given.pxPerM, p};
    if (given.pxOrigin)
        if (std::string p = parsePxOrigin(*given.pxOrigin, read.originPx); !p.empty())
            return TraceUnitsRefusal{kPxOriginOption.flag, *given.pxOrigin, p};
    spec = read;
    return std::nullopt;
}

std::string parsePxOrigin(const std::string& text, Vec2& origin) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) return "must be X,Y in pixels, e.g. 40,30";
    Vec2 v;
    for (int k = 0; k < 2; ++k) {
        const std::string part = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
        if (std::string p = limits::textViolation(part, limits::kMagnitude, v[k]); !p.empty())
            return p;
    }
    origin = v;
    return "";
}

std::string traceBlockName(const Scene& scene, int index) {
    const std::string& name = scene.blocks[static_cast<std::size_t>(index)].name;
    return name.empty() ? "blocks[" + std::to_string(index) + "]" : name;
}

Vec2 positionToPixels(Vec2 m, const Bounds& bounds, const TraceUnitsSpec& u) {
    return {u.originPx.x + (m.x - bounds.min.x) * u.pxPerM,
            u.originPx.y + (bounds.max.y - m.y) * u.pxPerM};
}
Vec2 positionFromPixels(Vec2 px, const Bounds& bounds, const TraceUnitsSpec& u) {
    return {bounds.min.x + (px.x - u.originPx.x) / u.pxPerM,
            bounds.max.y - (px.y - u.originPx.y) / u.pxPerM};
}
Vec2 velocityFromPixels(Vec2 v, double dt, const TraceUnitsSpec& u) {
    return {v.x / (u.pxPerM * dt), -v.y / (u.pxPerM * dt)};
}

TraceResult readTrace(std::istream& in, const std::string& source, const Scene& scene, double dt,
                      const TraceUnitsSpec& units) {
    TraceResult result;
    const std::string name = printable(source, kPrintablePath);
    auto fail = [&](int line, std::size_t column, const std::string& message) {
        result.error.where = name + ":" + std::to_string(line) +
                             (column > 0 ? ":" + std::to_string(column) : std::string());
        result.error.message = message;
        return result;
    };

    // The header: the first line that is not empty.
    std::string line;
    bool tooLong = false;
    int lineNo = 0;
    for (;;) {
        if (!readLine(in, line, tooLong))
            return fail(std::max(lineNo, 1), 1,
                        lineNo == 0 ? "empty file: a trace has a header row (t, then NAME_x, "
                                      "NAME_y, NAME_vx, NAME_vy per block) and one row per frame"
                                    : "no header row and no rows, only empty lines");
        ++lineNo;
        if (tooLong)
            return fail(lineNo, kMaxTraceLineBytes + 1,
                        "a line longer than " + std::to_string(kMaxTraceLineBytes >> 20) +
                            " MiB: not a trace the sandbox reads");
        if (lineNo == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3); // BOM
        if (line.find_first_not_of(" \t") != std::string::npos) break;
    }
    const int headerLine = lineNo;
    const char separator = separatorOf(line);
    std::vector<Field> fields;
    std::size_t badColumn = 0;
    if (!splitFields(line, separator, fields, badColumn))
        return fail(headerLine, badColumn, "a quote that does not close");
    const std::size_t columns = fields.size();

    // Which column is the time, and which are each block's x, y, vx, vy.
    // A block is found by its name, else by its name without the mass ("m1 = 1 kg" is m1),
    // else by either in any case: a student names blocks as the code does.
    std::map<std::string, int> byName[4];
    for (int i = 0; i < static_cast<int>(scene.blocks.size()); ++i) {
        const std::string full = traceBlockName(scene, i), base = baseBlockName(full);
        const std::string keys[4] = {full, base, lower(full), lower(base)};
        for (int tier = 0; tier < 4; ++tier) {
            const auto [it, fresh] = byName[tier].emplace(keys[tier], i);
            if (!fresh && it->second != i) it->second = -1; // two blocks of one name: ambiguous
        }
    }
    auto findBlock = [&](const std::string& name) -> std::optional<int> {
        for (int tier = 0; tier < 4; ++tier) {
            const auto it = byName[tier].find(tier < 2 ? name : lower(name));
            if (it != byName[tier].end()) return it->second;
        }
        return std::nullopt;
    };
    std::optional<std::size_t> timeColumn;
    TimeColumn timeKind = TimeColumn::Seconds;
    std::map<int, std::array<std::optional<std::size_t>, 4>> blockColumns; // scene index -> cols
    std::vector<std::string> headerNames(columns);
    bool allNumbers = true;
    std::size_t ignored = 0;
    std::string firstIgnored;
    for (std::size_t c = 0; c < columns; ++c) {
        const std::string text = fieldText(line, fields[c]);
        double unused = 0.0;
        allNumbers &= parseCell(text, separator != ',' || fields[c].quoted, unused).empty();
        if (const auto kind = timeColumnOf(text); kind && !timeColumn) {
            timeColumn = c;
            timeKind = *kind;
            headerNames[c] = text;
            continue;
        }
        std::string block;
        int component = 0;
        if (splitColumnName(text, block, component)) {
            if (const std::optional<int> found = findBlock(block)) {
                if (*found < 0)
                    return fail(headerLine, fields[c].column,
                                "column " + inQuotes(text) +
                                    ": the scene has more than one block "
                                    "named " +
                                    inQuotes(block) + ", so the trace cannot tell them apart");
                auto& slot = blockColumns[*found][static_cast<std::size_t>(component)];
                if (slot)
                    return fail(headerLine, fields[c].column,
                                "column " + inQuotes(text) + " appears twice (also column " +
                                    std::to_string(*slot + 1) + ")");
                slot = c;
                headerNames[c] = text;
                continue;
            }
        }
        if (ignored++ == 0) firstIgnored = text;
    }
    if (allNumbers)
        return fail(headerLine, 1,
                    "no header row: the first line must name the columns (t, then NAME_x, NAME_y, "
                    "NAME_vx, NAME_vy per block)");
    if (!timeColumn)
        return fail(headerLine, 1,
                    "no time column: the header must have a column t (seconds) or frame (the "
                    "frame's number, 1 after the first step)");

    Trace trace;
    trace.source = source;
    trace.units = units;
    // Every block that moves must be traced; a static block may be left out (it never moves).
    std::vector<std::array<std::size_t, 4>> used;
    for (int i = 0; i < static_cast<int>(scene.blocks.size()); ++i) {
        const auto it = blockColumns.find(i);
        const bool moves = scene.blocks[static_cast<std::size_t>(i)].kind != BodyKind::Static;
        if (it == blockColumns.end()) {
            if (!moves) continue;
            return fail(headerLine, 0,
                        "no columns for block " + inQuotes(traceBlockName(scene, i)) +
                            ": expected " + inQuotes(traceBlockName(scene, i) + "_x") + ", " +
                            inQuotes(traceBlockName(scene, i) + "_y") + ", " +
                            inQuotes(traceBlockName(scene, i) + "_vx") + " and " +
                            inQuotes(traceBlockName(scene, i) + "_vy") +
                            " (the header's columns are separated by " + separatorName(separator) +
                            ")");
        }
        std::array<std::size_t, 4> cols{};
        for (int k = 0; k < 4; ++k) {
            if (!it->second[static_cast<std::size_t>(k)])
                return fail(headerLine, 0,
                            "block " + inQuotes(traceBlockName(scene, i)) + " has no column " +
                                inQuotes(traceBlockName(scene, i) + "_" + kComponents[k]));
            cols[static_cast<std::size_t>(k)] = *it->second[static_cast<std::size_t>(k)];
        }
        trace.blocks.push_back(i);
        used.push_back(cols);
    }
    if (ignored > 0)
        trace.notes.push_back(std::to_string(ignored) + " column" + (ignored == 1 ? "" : "s") +
                              " not compared (" + inQuotes(firstIgnored) +
                              (ignored > 1 ? " and others" : "") +
                              "): not a block of the scene's x, y, vx or vy");

    const bool gxp = units.units == TraceUnits::Gxp;
    const std::size_t perRow = 4 * trace.blocks.size();
    for (;;) {
        if (!readLine(in, line, tooLong)) break;
        ++lineNo;
        if (tooLong)
            return fail(lineNo, kMaxTraceLineBytes + 1,
                        "a line longer than " + std::to_string(kMaxTraceLineBytes >> 20) + " MiB");
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (!splitFields(line, separator, fields, badColumn))
            return fail(lineNo, badColumn, "a quote that does not close");
        if (fields.size() != columns)
            return fail(lineNo, fields.size() < columns ? line.size() + 1 : fields[columns].column,
                        std::to_string(fields.size()) + " fields, the header (line " +
                            std::to_string(headerLine) + ") has " + std::to_string(columns) +
                            " (fields are separated by " + separatorName(separator) + ")");
        if ((trace.rows.size() + 1) * perRow > kMaxTraceValues)
            return fail(lineNo, 0,
                        "more than " + limits::formatNumber(static_cast<double>(kMaxTraceValues)) +
                            " numbers (" + std::to_string(trace.rows.size()) + " frames of " +
                            std::to_string(trace.blocks.size()) +
                            " blocks): a trace the sandbox compares is shorter");
        auto cell = [&](std::size_t c, double& value) -> bool {
            const std::string problem =
                parseCell(fieldText(line, fields[c]), separator != ',' || fields[c].quoted, value);
            if (problem.empty()) return true;
            fail(lineNo, fields[c].column, "column " + inQuotes(headerNames[c]) + ": " + problem);
            return false;
        };
        TraceRow row;
        row.line = lineNo;
        double t = 0.0;
        if (!cell(*timeColumn, t)) return result;
        const double frame = timeKind == TimeColumn::Frame ? t : t / dt;
        const double whole = std::round(frame);
        if (!(std::abs(frame - whole) <= (timeKind == TimeColumn::Frame ? 1e-6 : 0.25)) ||
            whole < 0.0 || whole > limits::kFrames.max)
            return fail(lineNo, fields[*timeColumn].column,
                        "column " + inQuotes(headerNames[*timeColumn]) + ": " +
                            limits::formatNumber(t) +
                            (timeKind == TimeColumn::Frame
                                 ? " is not a frame number from 0 to 1e7"
                                 : " s is not the end of a frame (dt " + limits::formatNumber(dt) +
                                       " s) from 0 to the frame budget, 1e7 frames"));
        row.frame = static_cast<std::int64_t>(whole);
        if (!trace.rows.empty() && row.frame <= trace.rows.back().frame)
            return fail(lineNo, fields[*timeColumn].column,
                        "column " + inQuotes(headerNames[*timeColumn]) + ": frame " +
                            std::to_string(row.frame) + " does not come after frame " +
                            std::to_string(trace.rows.back().frame) + " (line " +
                            std::to_string(trace.rows.back().line) + ")");
        for (std::size_t b = 0; b < trace.blocks.size(); ++b) {
            double v[4];
            for (std::size_t k = 0; k < 4; ++k)
                if (!cell(used[b][k], v[k])) return result;
            Vec2 p{v[0], v[1]}, w{v[2], v[3]};
            if (gxp) {
                p = positionFromPixels(p, scene.bounds, units);
                w = velocityFromPixels(w, dt, units);
            }
            // The limits of scene files, in the sandbox's units.
            for (std::size_t k = 0; k < 4; ++k) {
                const double si = k == 0 ? p.x : k == 1 ? p.y : k == 2 ? w.x : w.y;
                const std::string problem =
                    limits::violation(k < 2 ? limits::kCoordinate : limits::kSpeed, si);
                if (!problem.empty())
                    return fail(lineNo, fields[used[b][k]].column,
                                "column " + inQuotes(headerNames[used[b][k]]) + ": " + problem +
                                    (gxp ? " (in m or m/s, from the pixels)" : ""));
            }
            row.position.push_back(p);
            row.velocity.push_back(w);
        }
        trace.rows.push_back(std::move(row));
    }
    if (trace.rows.empty())
        return fail(headerLine + 1, 0, "no rows after the header: one row per frame is compared");
    result.trace = std::move(trace);
    return result;
}

TraceResult loadTraceFile(const std::string& path, const Scene& scene, double dt,
                          const TraceUnitsSpec& units) {
    TraceResult r;
    if (auto error = regularFileError(path)) {
        r.error = {error->where, error->message};
        return r;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.error = {printable(path, kPrintablePath), "cannot open the file"};
        return r;
    }
    return readTrace(in, path, scene, dt, units);
}
