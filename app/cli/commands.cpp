// sandbox-cli run and validate (docs/cli.md).
#include "commands.h"

#include "cli_print.h"

#include "csv.h"
#include "edit_log.h"

#include "input_limits.h"
#include "lesson_runner.h"
#include "printable.h"
#include "safe_file.h"
#include "scene.h"
#include "scene_json.h"
#include "world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <optional>
#include <ostream>

namespace {

// ---- Option values: the scene format's limits (input_limits.h), the same text rules for every
// flag ----

// How long to run: a number of frames, or until a simulated time.
struct StopRule {
    std::int64_t frames = kDefaultSteps; // the frame limit (for --time: the event-cap backstop)
    std::optional<double> time;          // s, with --time
};

// A flag's value refused: the flag, its value (printable and cut) and what it must be.
bool refuse(std::ostream& err, const char* option, const std::string& value,
            const std::string& expected) {
    err << "sandbox-cli run: " << option << " " << printable(value) << ": " << expected << "\n";
    return false;
}

// Parses `text` as a number within `range`; false with a message naming the flag and the limit.
bool numberOption(const char* option, const std::string& text, const limits::Range& range,
                  double& value, std::ostream& err) {
    if (std::string problem = limits::textViolation(text, range, value); !problem.empty())
        return refuse(err, option, text, problem);
    return true;
}

// Stops the run at `t` simulated seconds. The frame budget holds for the frames T needs at this
// dt; the backstop for an event cap that holds time back (100·T/dt frames) stops at the budget too.
bool stopAtTime(double t, const WorldSettings& s, const char* what, const std::string& text,
                StopRule& stop, std::ostream& err) {
    const double frames = std::ceil(t / s.dt);
    if (frames > limits::kFrames.max)
        return refuse(err, what, text,
                      "needs " + limits::formatNumber(frames) + " frames at dt " +
                          limits::formatNumber(s.dt) + " s, more than the frame budget (" +
                          limits::describe(limits::kFrames) + "): at most " +
                          limits::formatNumber(limits::kFrames.max * s.dt) + " s at this dt");
    stop.time = t;
    stop.frames =
        static_cast<std::int64_t>(std::min(std::ceil(100.0 * t / s.dt), limits::kFrames.max));
    return true;
}

// Applies the settings' flags to the scene's settings. Returns false and writes a message naming
// the flag and the limit on a bad value.
bool applyFlags(const RunRequest& r, WorldSettings& s, std::ostream& err) {
    for (const SettingFlag& flag : r.settings) {
        const settings_table::FlagProblem problem =
            settings_table::readFlag(*flag.row, flag.text, s);
        if (!problem.expected.empty())
            return refuse(err, flag.row->cli.flag, problem.text, problem.expected);
    }
    return true;
}

// How long the run is (--steps, --time, else the scene's duration), at the world's dt.
bool stopRule(const RunRequest& r, std::optional<double> duration, const WorldSettings& s,
              StopRule& stop, std::ostream& err) {
    if (r.steps) {
        double n = 0.0;
        if (!numberOption("--steps", *r.steps, limits::kFrames, n, err)) return false;
        stop.frames = static_cast<std::int64_t>(n);
    }
    if (r.time) {
        double t = 0.0;
        if (!numberOption("--time", *r.time, limits::kTime, t, err)) return false;
        return stopAtTime(t, s, "--time", *r.time, stop, err);
    }
    // Neither --steps nor --time: a scene that states how long it is watched runs that long.
    if (!r.steps && duration)
        return stopAtTime(*duration, s, "the scene's duration", limits::formatNumber(*duration),
                          stop, err);
    return true;
}

// ---- Edits (docs/edits.md): --set at frame 0, the --edits log's lines at their frames ----

// The world run and its blocks' names, changed only through `history` (app/edit).
struct EditedWorld {
    World world;
    std::vector<BlockLabel> labels;
    EditHistory history;
    std::optional<LogPlayer> log;
    bool fixedBlocks = false; // --trace: its columns are the blocks at the start
    EditTarget target() { return {world, labels}; }
};

bool applySets(const RunRequest& r, EditedWorld& w, std::ostream& err) {
    for (const std::string& text : r.sets) {
        EditError error;
        std::optional<Edit> edit = parseSet(text, error);
        if (edit) error = w.history.apply(w.target(), *edit, w.world.frame).error;
        if (!error.empty()) return refuse(err, "--set", text, printable(error.text()));
    }
    return true;
}

// The log's lines due at the world's frame; false with the line's place and why on a refusal.
bool playDueEdits(EditedWorld& w, std::ostream& err) {
    if (!w.log) return true;
    while (const LogLine* line = w.log->next(w.world.frame)) {
        const JournalEntry& e = line->entry;
        EditError error;
        if (e.what == JournalEntry::What::Undo) {
            error = w.history.undo(w.target(), w.world.frame).error;
        } else if (e.what == JournalEntry::What::Redo) {
            error = w.history.redo(w.target(), w.world.frame).error;
        } else if (w.fixedBlocks &&
                   (e.edit.kind == Edit::Kind::Add || e.edit.kind == Edit::Kind::Remove)) {
            error = {editKey(e.edit), "--trace writes the blocks of the start: a block may not be "
                                      "added or removed"};
        } else {
            error = w.history.apply(w.target(), e.edit, w.world.frame, e.continues).error;
        }
        if (error.empty()) continue;
        err << logLineError(*line, error).text() << "\n";
        return false;
    }
    return true;
}

// ---- --trace: one CSV row per frame, for a spreadsheet ----

void writeTraceHeader(std::ostream& out, const std::vector<BlockLabel>& labels) {
    out << "t";
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const std::string name =
            labels[i].name.empty() ? "blocks[" + std::to_string(i) + "]" : labels[i].name;
        for (const char* column : {" x", " y", " vx", " vy"}) out << ',' << csvField(name + column);
    }
    out << ",momentum_x,momentum_y,kinetic_energy,potential_energy\n";
}

// t (s), per block position (m) and velocity (m/s), totals: momentum (kg m/s), energies (J).
void writeTraceRow(std::ostream& out, const World& world, const StepStats& s) {
    out << world.time;
    for (const Block& b : world.blocks)
        out << ',' << b.position.x << ',' << b.position.y << ',' << b.velocity.x << ','
            << b.velocity.y;
    out << ',' << s.momentum.x << ',' << s.momentum.y << ',' << s.kineticEnergy << ','
        << s.potentialEnergy << '\n';
}

// What a run adds up over its steps, whether SIGINT stopped it before its end, and whether an
// edit of the log was refused (the message is out).
struct RunTotals {
    StepTotals steps;
    bool interrupted = false;
    bool refused = false;
};

// Progress on stderr for runs longer than a second: a line rewritten in place on a terminal,
// one line per report otherwise (--progress).
class Progress {
  public:
    Progress(const RunRequest& r, std::int64_t frames, std::ostream& err)
        : on_(r.progress != ProgressLines::Off), rewrite_(r.progress == ProgressLines::Terminal),
          frames_(frames), err_(err), next_(std::chrono::steady_clock::now() + kEvery) {}
    ~Progress() {
        if (shown_ && rewrite_) err_ << "\n";
    }
    void update(std::int64_t frame, double simulated) {
        if (!on_) return;
        const auto now = std::chrono::steady_clock::now();
        if (now < next_) return;
        next_ = now + kEvery;
        shown_ = true;
        err_ << (rewrite_ ? "\r" : "") << "sandbox-cli run: frame " << frame << " of " << frames_
             << " (" << limits::formatNumber(std::floor(1000.0 * frame / frames_) / 10.0) << "%), "
             << limits::formatNumber(simulated) << " s simulated; Ctrl+C stops and "
             << "prints the summary" << (rewrite_ ? "" : "\n") << std::flush;
    }

  private:
    static constexpr std::chrono::seconds kEvery{1};
    bool on_, rewrite_, shown_ = false;
    std::int64_t frames_;
    std::ostream& err_;
    std::chrono::steady_clock::time_point next_;
};

RunTotals simulate(EditedWorld& edited, const StopRule& stop, const RunRequest& request,
                   std::ostream* trace, std::ostream& err) {
    World& world = edited.world;
    RunTotals totals;
    Progress progress(request, stop.frames, err);
    // --time stops once the world time is within a tiny fraction of a frame of T, so rounding in
    // the sum of the frame lengths cannot add a frame.
    const double epsilon = 1e-6 * world.settings.dt;
    while (totals.steps.steps < stop.frames) {
        if (stop.time && world.time >= *stop.time - epsilon) break;
        if (request.interrupted && *request.interrupted) {
            totals.interrupted = true;
            break;
        }
        progress.update(totals.steps.steps, world.time);
        if (!playDueEdits(edited, err)) {
            totals.refused = true;
            return totals;
        }
        const StepStats s = world.step();
        if (trace) writeTraceRow(*trace, world, s);
        addStep(totals.steps, s);
    }
    // The lines of the last frame too (they show in the summary).
    totals.refused = !playDueEdits(edited, err);
    return totals;
}

// No silent blow-up: where nothing adds energy (no thrust, no moving platform), kinetic plus
// potential energy may not grow past kEnergyGrowthWarning times its start unnoticed. Where it does,
// the method fails at these settings (README, "Energy at the extremes"): the run is
// as simulated, and stderr says so.
constexpr double kEnergyGrowthWarning = 10.0;

void warnEnergyGrowth(const World& world, double before, std::ostream& err) {
    for (const Block& b : world.blocks)
        if (b.kind == BodyKind::Kinematic || b.force.x != 0.0 || b.force.y != 0.0) return;
    const double after = kineticEnergy(world) + potentialEnergy(world);
    if (!(before > 0.0) || !(after > kEnergyGrowthWarning * before)) return;
    err << "sandbox-cli run: warning: kinetic plus potential energy grew from "
        << limits::formatNumber(before) << " J to " << limits::formatNumber(after) << " J (x"
        << limits::formatNumber(std::round(after / before)) << ") with nothing adding any: the "
        << methodName(world.settings.method)
        << " method creates it at these settings (README, \"Energy at the "
           "extremes\")\n";
}

void printJson(const Scene& scene, const World& world, const std::vector<BlockLabel>& labels,
               const StepTotals& t, bool interrupted, std::ostream& out) {
    nlohmann::ordered_json j;
    const WorldSettings& s = world.settings;
    j["scene"] = scene.name; // dump() below escapes every control character
    for (const settings_table::WorldKey* row : settings_table::cliOrder())
        j[row->key] = settingJson(*row, s);
    j["sim_time"] = world.time;
    j["steps"] = t.steps;
    j["collisions"] = t.collisions;
    j["contacts"] = t.contacts;
    j["max_penetration"] = t.maxPenetration;
    j["momentum"] = vecJson(totalMomentum(world));
    j["kinetic_energy"] = kineticEnergy(world);
    j["potential_energy"] = potentialEnergy(world);
    j["event_cap_hits"] = t.eventCapHits;
    j["wall_ms"] = t.stepMs; // inside World::step only
    j["interrupted"] = interrupted;
    nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        nlohmann::ordered_json b;
        b["name"] = i < labels.size() ? labels[i].name : std::string();
        b["position"] = vecJson(world.blocks[i].position);
        b["velocity"] = vecJson(world.blocks[i].velocity);
        blocks.push_back(std::move(b));
    }
    j["blocks"] = std::move(blocks);
    // ASCII only: names are \u-escaped, so no byte of them can act on a terminal.
    out << j.dump(-1, ' ', true, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

void printText(const Scene& scene, const World& world, const std::vector<BlockLabel>& labels,
               const StepTotals& t, bool interrupted, std::ostream& out) {
    const WorldSettings& s = world.settings;
    const std::ios::fmtflags flags = out.flags();
    const std::streamsize precision = out.precision(6);
    out << "scene             " << printable(scene.name) << "\n"
        << "method            " << methodName(s.method) << "  (dt " << s.dt << " s, " << s.substeps
        << (s.substeps == 1 ? " substep" : " substeps") << ", bounciness " << s.bounciness
        << ", gravity " << s.gravity << " m/s^2)\n"
        << "steps             " << t.steps << "  (" << world.time << " s simulated"
        << (interrupted ? "; interrupted by Ctrl+C" : "") << ")\n"
        << "collisions        " << t.collisions << "\n"
        << "contacts          " << t.contacts << "  (resting, by the rest rule)\n"
        << "momentum          " << totalMomentum(world) << " kg m/s\n"
        << "kinetic energy    " << kineticEnergy(world) << " J\n"
        << "potential energy  " << potentialEnergy(world) << " J\n"
        << "max penetration   " << t.maxPenetration << " m\n"
        << "event-cap hits    " << t.eventCapHits << "\n"
        << "wall time         " << std::fixed << std::setprecision(3) << t.stepMs
        << " ms in steps\n";
    out.flags(flags);
    out.precision(6);
    if (world.blocks.size() <= 20) {
        for (std::size_t i = 0; i < world.blocks.size(); ++i) {
            const std::string name = printable(i < labels.size() ? labels[i].name : "", 40);
            out << "  " << std::left << std::setw(16)
                << (name.empty() ? "blocks[" + std::to_string(i) + "]" : name) << std::right
                << " position " << world.blocks[i].position << "  velocity "
                << world.blocks[i].velocity << "\n";
        }
    } else {
        out << "  (" << world.blocks.size() << " blocks; use --json for every block)\n";
    }
    out.flags(flags);
    out.precision(precision);
}

} // namespace

int runCommand(const RunRequest& request, std::ostream& out, std::ostream& err) {
    const SceneResult loaded = loadSceneFile(request.scene);
    if (!loaded.scene) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    Scene scene = *loaded.scene;
    if (!applyFlags(request, scene.settings, err)) return kExitBadInput;
    EditedWorld edited;
    edited.world = makeWorld(scene);
    for (const BlockDef& def : scene.blocks) edited.labels.push_back({def.name, def.color});
    if (!applySets(request, edited, err)) return kExitBadInput;
    if (request.edits) {
        EditLogResult log = readEditLog(*request.edits);
        if (!log.log) {
            err << log.error.text() << "\n";
            return kExitBadInput;
        }
        edited.log.emplace(std::move(*log.log));
    }
    World& world = edited.world;
    StopRule stop;
    if (!stopRule(request, scene.duration, world.settings, stop, err)) return kExitBadInput;
    std::optional<SafeFile> trace;
    if (request.trace) {
        // Written beside its target and renamed over it when complete: never onto the scene read.
        if (sameExistingFile(*request.trace, request.scene)) {
            err << "sandbox-cli run: --trace " << printable(*request.trace, kPrintablePath)
                << ": is the scene file being run; the output may not overwrite its input\n";
            return kExitBadInput;
        }
        trace.emplace(*request.trace);
        std::string error;
        if (!trace->opened(&error)) {
            err << "sandbox-cli run: --trace " << error << "\n";
            return kExitBadInput;
        }
        trace->stream() << std::setprecision(17);
        writeTraceHeader(trace->stream(), edited.labels);
        edited.fixedBlocks = true;
    }
    const double energyBefore = kineticEnergy(world) + potentialEnergy(world);
    const RunTotals run = simulate(edited, stop, request, trace ? &trace->stream() : nullptr, err);
    if (run.refused) return kExitBadInput; // the trace is not written: its run did not end
    if (edited.log && edited.log->remaining() > 0)
        err << "sandbox-cli run: --edits " << printable(*request.edits, kPrintablePath) << ": "
            << edited.log->remaining() << " line(s) after the run's last frame (" << world.frame
            << ") not applied\n";
    if (!edited.log) warnEnergyGrowth(world, energyBefore, err); // a log's edits may add energy
    std::string error;
    if (trace && !trace->commit(&error)) {
        err << "sandbox-cli run: --trace " << error << "\n";
        return kExitBadInput;
    }
    if (request.json)
        printJson(scene, world, edited.labels, run.steps, run.interrupted, out);
    else
        printText(scene, world, edited.labels, run.steps, run.interrupted, out);
    return run.interrupted ? kExitInterrupted : kExitOk;
}

int validateCommand(const std::string& path, std::ostream& out, std::ostream& err,
                    const LessonContext& lessons) {
    if (isLessonFile(path)) {
        const LessonResult lesson = loadLessonFile(path, lessons);
        if (!lesson.lesson) {
            err << printable(lesson.error.text(), kPrintablePath) << "\n";
            return kExitBadInput;
        }
        const std::vector<std::string> failures = checkLesson(*lesson.lesson);
        for (const std::string& f : failures) err << printable(f, kPrintablePath) << "\n";
        if (!failures.empty()) return kExitBadInput;
        out << "ok\n";
        return kExitOk;
    }
    const SceneResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    out << "ok\n";
    return kExitOk;
}
