#include "report.h"

#include "input_limits.h"
#include "inspector_format.h"
#include "printable.h"
#include "scene_json.h"
#include "settings_table.h"
#include "text_format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace {

using Json = nlohmann::ordered_json;

const char* kComponentNames[2][2] = {{"x", "y"}, {"vx", "vy"}};

std::string nameOf(const Scene& scene, int index) {
    if (index < 0) return wallName(index);
    return printable(traceBlockName(scene, index), 60);
}

std::string frameTime(const WorldSettings& s, std::int64_t frame) {
    return formatQuantity(static_cast<double>(frame) * s.dt, "s");
}

std::string quantity(const Difference& d, double value) {
    return formatQuantity(value, d.velocity ? "m/s" : "m");
}

std::string differenceSentence(const Scene& scene, const WorldSettings& s, const Difference& d) {
    return "frame " + std::to_string(d.frame) + " (t = " + frameTime(s, d.frame) + ", line " +
           std::to_string(d.line) + "): " + differenceName(scene, d) + " is " +
           quantity(d, d.yours) + ", the reference's " + quantity(d, d.reference) + " (off by " +
           quantity(d, d.by()) + ")";
}

// "method turn-based + mistake move-back: <says>; <says> (slides 'A', 'B')"
std::string variantSays(const Variant& v) {
    std::string says, slides;
    for (const Change& c : v.changes) {
        if (!says.empty()) says += "; and ";
        says += changeSays(c);
        if (!slides.empty()) slides += ", ";
        slides += "'" + changeSlide(c) + "'";
    }
    return says + " (" + (v.changes.size() > 1 ? "slides " : "slide ") + slides + ")";
}

std::string closeness(const RunMatch& m, std::int64_t frames) {
    return "it reproduces your trace to within " + formatQuantity(m.maxPositionError, "m") +
           " and " + formatQuantity(m.maxVelocityError, "m/s") + " over its " +
           std::to_string(frames) + (frames == 1 ? " frame" : " frames");
}

Json differenceJson(const Scene& scene, const WorldSettings& s, const Difference& d) {
    if (!d.found()) return nullptr;
    Json j;
    j["frame"] = d.frame;
    j["time"] = static_cast<double>(d.frame) * s.dt;
    j["line"] = d.line;
    j["block"] = traceBlockName(scene, d.block);
    j["quantity"] = kComponentNames[d.velocity][d.axis];
    j["yours"] = d.yours;
    j["reference"] = d.reference;
    j["by"] = d.by();
    return j;
}

Json vecJson(Vec2 v) {
    return Json::array({v.x, v.y});
}

// Every world key of the settings table, as sandbox-cli run --json writes them (its order and
// values), so a new key is in the report without a word here.
Json settingsJson(const WorldSettings& s) {
    Json j;
    for (const settings_table::WorldKey* row : settings_table::cliOrder())
        j[row->key] = settingJson(*row, s);
    return j;
}

// The same as text: "method perfect, dt 0.1 s, substeps 1, bounciness 1, gravity (0, 0) m/s², ...",
// each value as people read it (the panel's words), dt as seconds.
std::string settingsText(const WorldSettings& s) {
    std::string out;
    for (const settings_table::WorldKey* row : settings_table::cliOrder()) {
        settings_table::WorldKey plain = *row;
        plain.shown.asRate = false; // dt in seconds, as the trace's frames count them
        std::string value =
            settings_table::shownValue(plain, s, [](double v) { return formatNumber(v); });
        if (settings_table::isNone(*row, s) && row->kind == settings_table::Kind::NameSet)
            value = "none";
        out += (out.empty() ? "" : ", ") + std::string(row->key) + " " + value;
    }
    return out;
}

Json fitJson(const VariantFit& f) {
    Json j;
    j["name"] = variantName(f.variant.changes);
    Json changes = Json::array();
    for (const Change& c : f.variant.changes)
        changes.push_back(
            {{"change", changeName(c)}, {"says", changeSays(c)}, {"slide", changeSlide(c)}});
    j["changes"] = changes;
    j["settings"] = settingsJson(f.variant.settings);
    Json twins = Json::array();
    for (const Variant& v : f.sameAs)
        twins.push_back({{"name", variantName(v.changes)}, {"settings", settingsJson(v.settings)}});
    j["same_as"] = twins;
    j["same"] = f.match.same();
    j["same_until_frame"] = f.match.same() ? f.match.lastFrame : f.match.first().frame - 1;
    j["max_position_error"] = f.match.maxPositionError;
    j["max_velocity_error"] = f.match.maxVelocityError;
    return j;
}

} // namespace

std::string differenceName(const Scene& scene, const Difference& d) {
    return nameOf(scene, d.block) + "'s " + kComponentNames[d.velocity][d.axis];
}

std::vector<std::string> diagnosisLines(const TraceComparison& c) {
    std::vector<std::string> lines;
    if (c.same()) {
        lines.push_back("Your trace is the reference's within the tolerance: your engine does what "
                        "the lecture's does here.");
        return lines;
    }
    const PartingCollision& p = c.parting;
    if (!c.explaining.empty()) {
        const VariantFit& best = c.explaining.front();
        lines.push_back("Your engine behaves like the reference with " +
                        variantName(best.variant.changes) + ": " + variantSays(best.variant) +
                        "; " + closeness(best.match, c.frames) + ".");
        for (std::size_t i = 1; i < c.explaining.size() && i < 4; ++i)
            lines.push_back(
                "Also within the tolerance: " + variantName(c.explaining[i].variant.changes) +
                " (" + closeness(c.explaining[i].match, c.frames) + ").");
    }
    for (const Finding& f : p.findings)
        lines.push_back(std::string(p.inPartingFrame ? "At the collision where your engine parts "
                                                       "from the reference, "
                                                     : "Where your engine parts from the "
                                                       "reference, ") +
                        f.says + (f.slide.empty() ? "" : " (slide '" + f.slide + "')") + ".");
    if (c.explaining.empty()) {
        if (p.findings.empty())
            lines.push_back("Nothing the sandbox models explains your trace: no method, mistake, "
                            "resolve or integrator reproduces it, and your state where it parts "
                            "from the reference matches none of the lecture's rules.");
        else if (std::all_of(p.findings.begin(), p.findings.end(),
                             [](const Finding& f) { return f.convention; }))
            lines.push_back("Up to there your engine is the reference's; what follows grows from "
                            "this one difference.");
        else
            lines.push_back("No variant the sandbox simulates reproduces your whole trace; the "
                            "above is what your engine does differently.");
        if (c.closest) {
            const RunMatch& m = c.closest->match;
            lines.push_back("Closest: " + variantName(c.closest->variant.changes) +
                            ", the same up to frame " + std::to_string(m.first().frame - 1) +
                            " (largest difference " + formatQuantity(m.maxPositionError, "m") +
                            ").");
        }
    }
    return lines;
}

std::string reportText(const TraceComparison& c, const ReportContext& ctx) {
    const Scene& scene = *ctx.scene;
    const Trace& trace = *ctx.trace;
    const WorldSettings& s = c.reference;
    std::string out;
    auto line = [&](const std::string& text) { out += text + "\n"; };
    line("scene      " + printable(scene.name) + " (" + printable(ctx.scenePath, 200) + ")");
    line("reference  " + settingsText(s));
    std::string blocks;
    for (std::size_t i = 0; i < trace.blocks.size() && i < 8; ++i)
        blocks += (i ? ", " : "") + nameOf(scene, trace.blocks[i]);
    if (trace.blocks.size() > 8) blocks += ", ...";
    std::string units = "SI units (m, m/s, y up)";
    if (trace.units.units == TraceUnits::Gxp)
        units =
            "gxp units (" + formatNumber(trace.units.pxPerM) +
            " px/m, y down, velocities in px per frame, the world's top-left corner at pixel (" +
            formatNumber(trace.units.originPx.x) + ", " + formatNumber(trace.units.originPx.y) +
            "))";
    line("trace      " + printable(trace.source, 200) + ": " + std::to_string(c.frames) +
         (c.frames == 1 ? " frame" : " frames") + " (" + std::to_string(trace.rows.front().frame) +
         " to " + std::to_string(trace.rows.back().frame) + "), " +
         std::to_string(trace.blocks.size()) +
         (trace.blocks.size() == 1 ? " block (" : " blocks (") + blocks + "), " + units);
    line("tolerance  " + limits::formatNumber(c.tolerance.position) + " m for positions, " +
         limits::formatNumber(c.tolerance.velocity) + " m/s for velocities: " + c.tolerance.why);
    for (const std::string& note : trace.notes) line("note       " + note);
    for (const std::string& note : c.notes) line("note       " + note);
    line("");
    const RunMatch& m = c.match;
    if (c.same()) {
        line("SAME as the reference within the tolerance over " + std::to_string(c.frames) +
             " frames (largest differences " + formatQuantity(m.maxPositionError, "m") + " and " +
             formatQuantity(m.maxVelocityError, "m/s") + ").");
        if (m.resting.found())
            line("Velocities differ only where the reference's block rests, from " +
                 differenceSentence(scene, s, m.resting) +
                 ": a velocity its position never shows (gravity's g·dt printed before the "
                 "floor took it away?).");
        return out;
    }
    line("DIFFERENT from " + differenceSentence(scene, s, m.first()));
    const Difference& other = &m.first() == &m.position ? m.velocity : m.position;
    if (other.found())
        line("  first " + std::string(other.velocity ? "velocity" : "position") +
             " difference: " + differenceSentence(scene, s, other));
    else
        line(std::string("  the ") + (m.position.found() ? "velocities" : "positions") +
             " agree within the tolerance throughout");
    line("  over the whole trace: positions up to " + formatQuantity(m.maxPositionError, "m") +
         " apart, velocities up to " + formatQuantity(m.maxVelocityError, "m/s"));
    line("");
    const PartingCollision& p = c.parting;
    if (p.found) {
        const CollisionRecord& r = p.record;
        line(std::string(p.frame > m.first().frame
                             ? "The reference's collision right after it"
                             : "The reference's collision nearest before it") +
             ": frame " + std::to_string(p.frame) + " (t = " + frameTime(s, p.frame - 1) + " to " +
             frameTime(s, p.frame) + ")" +
             (p.inPartingFrame ? ", the frame where your engine parts from it" : ""));
        const CollisionFormula f =
            collisionFormula(r, nameOf(scene, r.block), nameOf(scene, r.other));
        line("  " + f.title);
        line("  " + f.relative);
        line("  " + f.u);
        line("  " + f.v1After);
        if (!f.v2After.empty()) line("  " + f.v2After);
        if (p.poi.valid && p.inPartingFrame)
            line("  point of impact of " + nameOf(scene, p.block) + ": " + poiEquation(p.poi) +
                 ", POI = (" + formatNumber(p.poi.ghost.x) + ", " + formatNumber(p.poi.ghost.y) +
                 ")");
        if (p.yoursKnown && p.inPartingFrame)
            line("  at the frame's end, " + nameOf(scene, p.block) + ": velocity yours (" +
                 formatNumber(p.yoursVelocity.x) + ", " + formatNumber(p.yoursVelocity.y) +
                 ") m/s, the reference's (" + formatNumber(p.referenceVelocity.x) + ", " +
                 formatNumber(p.referenceVelocity.y) + "); position yours (" +
                 formatNumber(p.yoursPosition.x) + ", " + formatNumber(p.yoursPosition.y) +
                 ") m, the reference's (" + formatNumber(p.referencePosition.x) + ", " +
                 formatNumber(p.referencePosition.y) + ")");
    } else {
        line("The reference has no collision of " + nameOf(scene, m.first().block) +
             " before it: the difference is in the free flight (the forces and the integration).");
    }
    line("");
    line("Diagnosis");
    for (const std::string& d : diagnosisLines(c)) line("  " + d);
    return out;
}

std::string reportJson(const TraceComparison& c, const ReportContext& ctx) {
    const Scene& scene = *ctx.scene;
    const Trace& trace = *ctx.trace;
    const WorldSettings& s = c.reference;
    Json j;
    j["result"] = c.same() ? "same" : "different";
    j["scene"] = scene.name;
    j["scene_file"] = ctx.scenePath;
    j["reference"] = settingsJson(s);
    Json t;
    t["file"] = trace.source;
    t["frames"] = c.frames;
    t["first_frame"] = trace.rows.front().frame;
    t["last_frame"] = trace.rows.back().frame;
    Json names = Json::array();
    for (int b : trace.blocks) names.push_back(traceBlockName(scene, b));
    t["blocks"] = names;
    t["units"] = trace.units.units == TraceUnits::Gxp ? "gxp" : "si";
    if (trace.units.units == TraceUnits::Gxp) {
        t["px_per_m"] = trace.units.pxPerM;
        t["px_origin"] = vecJson(trace.units.originPx);
    }
    t["notes"] = trace.notes;
    j["trace"] = t;
    j["tolerance"] = {{"position", c.tolerance.position},
                      {"velocity", c.tolerance.velocity},
                      {"why", c.tolerance.why}};
    const RunMatch& m = c.match;
    j["first_difference"] = differenceJson(scene, s, m.first());
    j["first_position_difference"] = differenceJson(scene, s, m.position);
    j["first_velocity_difference"] = differenceJson(scene, s, m.velocity);
    j["resting_velocity_difference"] = differenceJson(scene, s, m.resting);
    j["max_position_error"] = m.maxPositionError;
    j["max_velocity_error"] = m.maxVelocityError;
    const PartingCollision& p = c.parting;
    if (p.found) {
        const CollisionRecord& r = p.record;
        Json col;
        col["frame"] = p.frame;
        col["in_parting_frame"] = p.inPartingFrame;
        col["time"] = r.time;
        col["block"] = r.block >= 0 ? traceBlockName(scene, r.block) : wallName(r.block);
        col["other"] = r.other >= 0 ? traceBlockName(scene, r.other) : wallName(r.other);
        col["axis"] = r.axis == 0 ? "x" : "y";
        col["m1"] = std::isfinite(r.m1) ? Json(r.m1) : Json("infinite");
        col["m2"] = std::isfinite(r.m2) ? Json(r.m2) : Json("infinite");
        col["v1"] = r.v1;
        col["v2"] = r.v2;
        col["u"] = r.u;
        col["C"] = r.C;
        col["v1_after"] = r.v1After;
        col["v2_after"] = r.v2After;
        if (p.poi.valid && p.inPartingFrame) {
            col["t"] = p.poi.t;
            col["a"] = p.poi.a;
            col["b"] = p.poi.b;
            col["poi"] = vecJson(p.poi.ghost);
        }
        if (p.yoursKnown && p.inPartingFrame) {
            col["yours_velocity"] = vecJson(p.yoursVelocity);
            col["reference_velocity"] = vecJson(p.referenceVelocity);
            col["yours_position"] = vecJson(p.yoursPosition);
            col["reference_position"] = vecJson(p.referencePosition);
        }
        j["collision"] = col;
    } else {
        j["collision"] = nullptr;
    }
    Json findings = Json::array();
    for (const Finding& f : p.findings)
        findings.push_back(
            {{"id", f.id}, {"says", f.says}, {"slide", f.slide}, {"convention", f.convention}});
    j["findings"] = findings;
    Json d;
    d["explained"] = !c.explaining.empty();
    d["variant"] = c.explaining.empty() ? Json(nullptr) : fitJson(c.explaining.front());
    Json also = Json::array();
    for (std::size_t i = 1; i < c.explaining.size(); ++i) also.push_back(fitJson(c.explaining[i]));
    d["also"] = also;
    d["closest"] = c.closest ? fitJson(*c.closest) : Json(nullptr);
    d["text"] = diagnosisLines(c);
    j["diagnosis"] = d;
    j["notes"] = c.notes;
    return j.dump(-1, ' ', true, Json::error_handler_t::replace) + "\n";
}
