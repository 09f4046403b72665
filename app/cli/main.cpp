// sandbox-cli: simulate or validate scene files without a window (docs/cli.md).
// Exit codes: 0 ok, 1 bad input (scene file or option value), 2 bad usage.
#include "analysis_commands.h"
#include "commands.h"
#include "compare_command.h"
#include "input_limits.h"
#include "poll_command.h"
#include "printable.h"
#include "settings_table.h"
#include "trace.h"      // the trace-units options' table
#include "vocabulary.h" // the overlay table (header-only): its names, for lesson files

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>

#include <unistd.h>

namespace {

volatile std::sig_atomic_t interrupted = 0;

// The first Ctrl+C ends `run` after the current frame (its summary is still printed); the
// handler is then reset, so a second one ends the process at once.
void onInterrupt(int) {
    interrupted = 1;
}

void stopOnInterrupt() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
}

// tradeoff's and stability's shared options: --out DIR (required) and --scenes DIR.
void addAnalysisOptions(CLI::App* command, AnalysisRequest& request) {
    command->add_option("--out", request.outDir, "Output directory (created if missing)")
        ->required()
        ->type_name("DIR");
    command->add_option("--scenes", request.scenesDir, "Directory of the scene files")
        ->type_name("DIR")
        ->capture_default_str();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Collision sandbox, headless: simulate or validate scene files (format v1).\n"
                 "Exit codes: 0 ok, 1 bad input (scene file or option value), 2 bad usage."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Print this help and the options of every subcommand");

    RunRequest run;
    CLI::App* runCmd = app.add_subcommand("run", "Simulate a scene and print a summary.");
    runCmd->add_option("SCENE", run.scene, "Scene file (JSON, format v1)")->required();
    // One flag per world setting that has one (settings_table.h), in sandbox-cli's order: the
    // placed ones (--method, --dt, ...) before --steps, the others after --progress.
    struct SettingText {
        const settings_table::WorldKey* row;
        std::string one;               // a flag given once
        std::vector<std::string> many; // a repeatable flag (a set of names: --mistake)
        CLI::Option* option;
    };
    std::vector<SettingText> settingFlags;
    for (const settings_table::WorldKey* row : settings_table::cliOrder())
        if (*row->cli.flag) settingFlags.push_back({row, {}, {}, nullptr});
    // The vector is not resized from here on: CLI11 keeps the addresses of `one` and `many`.
    auto addSettingFlags = [&](bool placed) {
        for (SettingText& flag : settingFlags) {
            if ((flag.row->cli.place > 0) != placed) continue;
            const std::string help = settings_table::flagHelp(*flag.row);
            flag.option = flag.row->kind == settings_table::Kind::NameSet
                              ? runCmd->add_option(flag.row->cli.flag, flag.many, help)
                              : runCmd->add_option(flag.row->cli.flag, flag.one, help);
            flag.option->type_name(flag.row->cli.value);
        }
    };
    addSettingFlags(true);
    std::string steps, time;
    using limits::describe;
    CLI::Option* stepsOpt = runCmd->add_option("--steps", steps,
                                               "Frames to simulate, " + describe(limits::kFrames) +
                                                   " (the frame budget; default: the scene's "
                                                   "\"duration\", else 600, i.e. 10 s at dt 1/60)");
    CLI::Option* timeOpt = runCmd->add_option(
        "--time", time,
        "Simulate until T seconds of simulated time (T/dt frames within the frame budget), or "
        "at most 100*T/dt frames (and the budget) if the event cap holds time back");
    stepsOpt->excludes(timeOpt);
    bool progressLines = false;
    runCmd->add_flag("--progress", progressLines,
                     "Report progress on stderr once a second, one line each (on a terminal a "
                     "line rewritten in place is the default)");
    addSettingFlags(false);
    std::string trace;
    CLI::Option* traceOpt = runCmd->add_option(
        "--trace", trace,
        "Write a CSV file: a header and one row per frame (t, each block's x, y, vx, vy, total "
        "momentum, kinetic and potential energy)");
    CLI::Option* setOpt = runCmd->add_option(
        "--set", run.sets,
        "Set a world key or a block's field before the first frame (repeatable, after the "
        "flags above): bounciness=0.5, m2.mass=4, blocks[1].velocity=3,0 (docs/edits.md)");
    std::string edits;
    CLI::Option* editsOpt = runCmd->add_option(
        "--edits", edits,
        "Replay an edit log: JSON lines, each an edit (set, add, remove), undo or redo with the "
        "frame it applies at (docs/edits.md)");
    runCmd->add_flag("--json", run.json,
                     "Print one JSON object: sim_time, steps, collisions, max_penetration, "
                     "momentum, kinetic_energy, potential_energy, event_cap_hits, wall_ms, blocks");
    stepsOpt->type_name("N");
    timeOpt->type_name("T");
    traceOpt->type_name("FILE.csv");
    setOpt->type_name("KEY=VALUE")->allow_extra_args(false); // one value per --set
    editsOpt->type_name("FILE.jsonl");

    std::string validatePath;
    CLI::App* validateCmd = app.add_subcommand(
        "validate", "Check a scene or lesson file: print ok (exit 0) or the error and its place "
                    "(exit 1).");
    validateCmd->add_option("FILE", validatePath, "Scene file (format v1) or lesson file (JSON)")
        ->required();

    std::string lessonPath;
    CLI::App* lessonCmd = app.add_subcommand(
        "lesson", "Run every step of a lesson to its pause point: print where each paused and "
                  "the blocks there, then any failed expectation (exit 1).");
    lessonCmd->add_option("LESSON", lessonPath, "Lesson file (JSON)")->required();
    bool lessonJson = false;
    lessonCmd->add_flag("--json", lessonJson,
                        "One JSON object: each step's pause time, frame, collisions, contacts, "
                        "time scale, seconds of motion, blocks and failures");

    AnalysisRequest tradeoff;
    tradeoff.scenesDir = SANDBOX_SCENES_DIR;
    CLI::App* tradeoffCmd = app.add_subcommand(
        "tradeoff", "Speed versus accuracy: every method (and Box2D when built with it) over dt "
                    "1/30..1/7680 and substeps 1 and 4 on scenes with known answers. Writes "
                    "tradeoff.csv, tradeoff.md and tradeoff.png.");
    addAnalysisOptions(tradeoffCmd, tradeoff);
    tradeoffCmd->add_flag("--quick", tradeoff.quick, "Three frame rates instead of nine");

    AnalysisRequest stability;
    stability.scenesDir = SANDBOX_SCENES_DIR;
    CLI::App* stabilityCmd = app.add_subcommand(
        "stability", "The stability matrix: failure scenes (tunnelling bullet, resting stack, "
                     "inelastic collapse, Newton's cradle, corner hit, high mass ratio, jammed "
                     "box) under every method, with the measured outcome of each. Writes "
                     "stability.csv and stability.md.");
    addAnalysisOptions(stabilityCmd, stability);
    stability.extremesDir = SANDBOX_EXTREMES_DIR;
    stabilityCmd
        ->add_option("--extremes", stability.extremesDir,
                     "Directory of the energy extremes' scenes (issue 28's rows; \"\": "
                     "left out)")
        ->type_name("DIR")
        ->capture_default_str();

    CompareRequest compare;
    CLI::App* compareCmd = app.add_subcommand(
        "compare", "Check your own engine: compare a trace your engine printed (CSV: t, then "
                   "NAME_x, NAME_y, NAME_vx, NAME_vy per block) with the reference; print the "
                   "first difference, the reference's collision before it and a diagnosis. "
                   "Exit 0 the same, 3 different, 1 bad input, 2 bad usage (docs/compare.md).");
    compareCmd->add_option("SCENE", compare.scene, "Scene file (JSON, format v1)")->required();
    compareCmd->add_option("TRACE", compare.trace, "Your engine's trace (CSV)")->required();
    std::string compareMethod, units, pxPerM, pxOrigin, tolerance;
    CLI::Option* compareMethodOpt = compareCmd->add_option(
        "--method", compareMethod,
        "The reference's method: perfect, move-and-correct or turn-based (default: the scene's)");
    // The trace's units: trace.h's table, shared with the app's --compare.
    CLI::Option* unitsOpt = compareCmd->add_option("--units", units, kTraceUnitsOption.help);
    CLI::Option* pxPerMOpt = compareCmd->add_option(kPxPerMOption.flag, pxPerM, kPxPerMOption.help);
    CLI::Option* pxOriginOpt =
        compareCmd->add_option(kPxOriginOption.flag, pxOrigin, kPxOriginOption.help);
    CLI::Option* toleranceOpt = compareCmd->add_option(
        "--tolerance", tolerance,
        "Positions within M metres are the same (default: a thousandth of the smallest block); "
        "velocities within M per frame");
    compareCmd->add_flag("--json", compare.json, "Print one JSON object");
    compareMethodOpt->type_name("M");
    unitsOpt->type_name(kTraceUnitsOption.value);
    pxPerMOpt->type_name(kPxPerMOption.value);
    pxOriginOpt->type_name(kPxOriginOption.value);
    toleranceOpt->type_name("M");

    PollCommandRequest poll;
    CLI::App* pollCmd = app.add_subcommand(
        "poll", "Serve a lesson's class poll (docs/poll.md): print {\"url\", \"token\"} as the "
                "first line, then read commands on stdin: open STEP, close, revote, status, save "
                "FILE.csv, quit; one JSON line answers each.");
    pollCmd->add_option("LESSON", poll.lesson, "Lesson file (JSON) whose steps ask with choices")
        ->required();
    pollCmd->add_option("--bind", poll.bind, "Address to listen on (default: the default route's)")
        ->type_name("ADDR");
    pollCmd->add_option("--port", poll.port, "Port (default 0: a free one)")->type_name("N");
    pollCmd->add_option("--csv", poll.csv, "Write every round's counts here at quit")
        ->type_name("FILE.csv");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help is a "parse error" with exit code 0; everything else is bad usage, and its
        // message (which quotes the arguments) is printed printable.
        if (e.get_exit_code() == 0) return app.exit(e) == 0 ? kExitOk : kExitUsage;
        std::cerr << "sandbox-cli: " << printable(e.what(), 4 * kPrintableDefault)
                  << "\nRun with --help for more information.\n";
        return kExitUsage;
    }

    try {
        LessonContext lessons;
        lessons.scenesDir = SANDBOX_SCENES_DIR;
        lessons.overlayNames = overlayNames();
        if (*validateCmd) return validateCommand(validatePath, std::cout, std::cerr, lessons);
        if (*pollCmd) return pollCommand(poll, lessons, std::cin, std::cout, std::cerr);
        if (*lessonCmd) return lessonCommand(lessonPath, std::cout, std::cerr, lessons, lessonJson);
        if (*tradeoffCmd) return tradeoffCommand(tradeoff, std::cout, std::cerr);
        if (*stabilityCmd) return stabilityCommand(stability, std::cout, std::cerr);
        auto given = [](CLI::Option* option, const std::string& value) {
            return option->count() > 0 ? std::optional<std::string>(value) : std::nullopt;
        };
        if (*compareCmd) {
            compare.method = given(compareMethodOpt, compareMethod);
            compare.units = given(unitsOpt, units);
            compare.pxPerM = given(pxPerMOpt, pxPerM);
            compare.pxOrigin = given(pxOriginOpt, pxOrigin);
            compare.tolerance = given(toleranceOpt, tolerance);
            return compareCommand(compare, std::cout, std::cerr);
        }
        for (const SettingText& flag : settingFlags) {
            if (flag.row->kind == settings_table::Kind::NameSet) {
                for (const std::string& text : flag.many) run.settings.push_back({flag.row, text});
            } else if (flag.option->count() > 0) {
                run.settings.push_back({flag.row, flag.one});
            }
        }
        run.steps = given(stepsOpt, steps);
        run.time = given(timeOpt, time);
        run.progress = progressLines ? ProgressLines::Lines
                       : isatty(2)   ? ProgressLines::Terminal
                                     : ProgressLines::Off;
        run.interrupted = &interrupted;
        stopOnInterrupt();
        run.trace = given(traceOpt, trace);
        run.edits = given(editsOpt, edits);
        return runCommand(run, std::cout, std::cerr);
    } catch (const std::exception& e) { // e.g. out of memory on a huge scene
        std::cerr << "sandbox-cli: " << e.what() << "\n";
        return kExitBadInput;
    }
}
