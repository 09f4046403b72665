// sandbox-cli run and validate (docs/cli.md).
#include "commands.h"

#include "csv.h"

#include "input_limits.h"
#include "lesson_prompt.h"
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

// Applies the command-line overrides to the scene's settings. Returns false and writes a message
// naming the option and the limit on a bad value.
bool applyOptions(const RunRequest& r, std::optional<double> duration, WorldSettings& s,
                  StopRule& stop, std::ostream& err) {
    for (const SettingFlag& flag : r.settings) {
        const settings_table::FlagProblem problem =
            settings_table::readFlag(*flag.row, flag.text, s);
        if (!problem.expected.empty())
            return refuse(err, flag.row->cli.flag, problem.text, problem.expected);
    }
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

// ---- --trace: one CSV row per frame, for a spreadsheet ----

void writeTraceHeader(std::ostream& out, const Scene& scene) {
    out << "t";
    for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
        const std::string name = scene.blocks[i].name.empty() ? "blocks[" + std::to_string(i) + "]"
                                                              : scene.blocks[i].name;
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

// What a run adds up over its steps, and whether SIGINT stopped it before its end.
struct RunTotals {
    StepTotals steps;
    bool interrupted = false;
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

RunTotals simulate(World& world, const StopRule& stop, const RunRequest& request,
                   std::ostream* trace, std::ostream& err) {
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
        const StepStats s = world.step();
        if (trace) writeTraceRow(*trace, world, s);
        addStep(totals.steps, s);
    }
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

nlohmann::ordered_json vecJson(Vec2 v) {
    return {v.x, v.y};
}

void printJson(const Scene& scene, const World& world, const StepTotals& t, bool interrupted,
               std::ostream& out) {
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
        b["name"] = i < scene.blocks.size() ? scene.blocks[i].name : std::string();
        b["position"] = vecJson(world.blocks[i].position);
        b["velocity"] = vecJson(world.blocks[i].velocity);
        blocks.push_back(std::move(b));
    }
    j["blocks"] = std::move(blocks);
    // ASCII only: names are \u-escaped, so no byte of them can act on a terminal.
    out << j.dump(-1, ' ', true, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

std::ostream& operator<<(std::ostream& out, Vec2 v) {
    return out << "(" << v.x << ", " << v.y << ")";
}

void printText(const Scene& scene, const World& world, const StepTotals& t, bool interrupted,
               std::ostream& out) {
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
            const std::string name = printable(scene.blocks[i].name, 40);
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
    StopRule stop;
    if (!applyOptions(request, scene.duration, scene.settings, stop, err)) return kExitBadInput;
    World world = makeWorld(scene);
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
        writeTraceHeader(trace->stream(), scene);
    }
    const double energyBefore = kineticEnergy(world) + potentialEnergy(world);
    const RunTotals run = simulate(world, stop, request, trace ? &trace->stream() : nullptr, err);
    warnEnergyGrowth(world, energyBefore, err);
    std::string error;
    if (trace && !trace->commit(&error)) {
        err << "sandbox-cli run: --trace " << error << "\n";
        return kExitBadInput;
    }
    if (request.json)
        printJson(scene, world, run.steps, run.interrupted, out);
    else
        printText(scene, world, run.steps, run.interrupted, out);
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

namespace {

// A text of several lines as one (its line breaks as spaces), safe to print.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return printable(text, kPrintablePath);
}

std::string blockLabel(const LessonStep& step, std::size_t b) {
    return step.scene->blocks[b].name.empty() ? "#" + std::to_string(b)
                                              : step.scene->blocks[b].name;
}

// One step as `lesson --json` lists it: where it pauses, what it counted, and the seconds of
// motion the class sees from its setup (t = 0) to that moment at its time scale.
nlohmann::ordered_json stepJson(std::size_t number, const LessonStep& step, const StepRun& run,
                                const std::vector<std::string>& failures) {
    nlohmann::ordered_json j;
    j["step"] = number;
    j["title"] = step.title;
    j["method"] = methodName(run.world.settings.method);
    j["reached"] = run.reached;
    j["pause_time"] = run.world.time;
    j["frame"] = run.progress.frames;
    j["collisions"] = run.progress.collisions;
    j["contacts"] = run.progress.contacts;
    j["time_scale"] = step.timeScale;
    j["motion_seconds"] = run.world.time / step.timeScale;
    j["event_time"] =
        run.reached ? nlohmann::ordered_json(run.event.time) : nlohmann::ordered_json();
    // What the step asks and answers, computed from the run (lesson_prompt.h): the question and
    // its choices at the setup, the choice the step marks correct, the ones the run proved.
    const StepPrompt prompt = stepPrompt(step);
    const StepAnswer answer = stepAnswer(step, run, {}, nullptr);
    j["question"] = prompt.question;
    nlohmann::ordered_json choices = nlohmann::ordered_json::array();
    for (std::size_t c = 0; c < prompt.choices.size(); ++c)
        choices.push_back({{"letter", choiceLetter(c)}, {"text", prompt.choices[c]}});
    j["choices"] = std::move(choices);
    j["correct"] =
        prompt.correct >= 0
            ? nlohmann::ordered_json(choiceLetter(static_cast<std::size_t>(prompt.correct)))
            : nlohmann::ordered_json();
    nlohmann::ordered_json proved = nlohmann::ordered_json::array();
    for (const int c : answer.proved) proved.push_back(choiceLetter(static_cast<std::size_t>(c)));
    j["proved"] = std::move(proved);
    j["answer"] = answer.text;
    j["missed"] = answer.missed;
    j["given"] = step.given.size(); // statements of the question checked at the setup
    // The blocks as the setup shows them (t = 0, the question asked), then at the moment.
    const auto blocksJson = [&step](const World& world, bool withSize) {
        nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
        for (std::size_t b = 0; b < world.blocks.size(); ++b) {
            nlohmann::ordered_json block;
            block["name"] = blockLabel(step, b);
            block["position"] = vecJson(world.blocks[b].position);
            block["velocity"] = vecJson(world.blocks[b].velocity);
            if (withSize) block["size"] = vecJson(world.blocks[b].size);
            blocks.push_back(std::move(block));
        }
        return blocks;
    };
    j["setup_blocks"] = blocksJson(stepStartWorld(step), true);
    j["blocks"] = blocksJson(run.world, false);
    j["failures"] = failures;
    return j;
}

} // namespace

int lessonCommand(const std::string& path, std::ostream& out, std::ostream& err,
                  const LessonContext& lessons, bool json) {
    const LessonResult loaded = loadLessonFile(path, lessons);
    if (!loaded.lesson) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    const Lesson& lesson = *loaded.lesson;
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    if (!json)
        out << printable(lesson.name, kPrintablePath) << ": " << lesson.steps.size() << " steps\n";
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        const StepRun run = runStepToPause(step);
        const std::vector<std::string> f = checkStep(step, run);
        failures.insert(failures.end(), f.begin(), f.end());
        if (json) {
            steps.push_back(stepJson(i + 1, step, run, f));
            continue;
        }
        out << i + 1 << ". " << printable(step.title, kPrintablePath) << ": "
            << (run.reached ? "paused" : "NOT PAUSED") << " at t = " << run.world.time
            << " s (frame " << run.progress.frames << "), " << run.progress.collisions
            << " collisions, " << run.progress.contacts << " contacts, "
            << methodName(run.world.settings.method) << "\n";
        // The question, its choices (the correct one marked, the ones the run proved) and the
        // answer, computed from the run (lesson_prompt.h).
        const StepPrompt prompt = stepPrompt(step);
        const StepAnswer answer = stepAnswer(step, run, {}, nullptr);
        if (!prompt.question.empty()) {
            out << "     Predict: " << oneLine(prompt.question) << "\n";
            for (std::size_t c = 0; c < prompt.choices.size(); ++c) {
                const bool proved = std::find(answer.proved.begin(), answer.proved.end(),
                                              static_cast<int>(c)) != answer.proved.end();
                out << "       " << choiceLetter(c) << ". " << oneLine(prompt.choices[c])
                    << (static_cast<int>(c) == prompt.correct ? "  (correct)" : "")
                    << (proved ? "  (proved)" : "") << "\n";
            }
        }
        if (!answer.missed.empty())
            out << "     No answer: " << oneLine(answer.missed) << "\n";
        else if (!answer.text.empty())
            out << "     Answer: " << oneLine(answer.text) << "\n";
        for (std::size_t b = 0; b < run.world.blocks.size() && b < 12; ++b) {
            const Block& block = run.world.blocks[b];
            out << "     " << std::left << std::setw(14) << printable(blockLabel(step, b))
                << std::right << " position " << block.position << "  velocity " << block.velocity
                << "\n";
        }
    }
    if (json) {
        nlohmann::ordered_json j;
        j["name"] = lesson.name;
        j["steps"] = std::move(steps);
        // ASCII only: names are \u-escaped, so no byte of them can act on a terminal.
        out << j.dump(-1, ' ', true, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    }
    for (const std::string& f : failures) err << printable(f, kPrintablePath) << "\n";
    return failures.empty() ? kExitOk : kExitBadInput;
}
