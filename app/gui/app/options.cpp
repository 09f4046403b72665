#include "options.h"

#include "input_limits.h"
#include "input_map.h"
#include "printable.h"
#include "safe_file.h"
#include "view.h" // the UI scale's range

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <utility>

bool parseSize(const std::string& text, int& width, int& height) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3) return false;
    if (x != 'x' && x != 'X') return false;
    if (w < 16 || h < 16 || w > 16384 || h > 16384) return false;
    width = w;
    height = h;
    return true;
}

bool parseScreens(const std::string& text, std::vector<ClassroomScreen>& out, std::string* error) {
    out.clear();
    if (text == "all") {
        out = classroomScreens();
        return true;
    }
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        const std::size_t at = item.find('@');
        ClassroomScreen screen;
        char* rest = nullptr;
        const std::string scale = at == std::string::npos ? "" : item.substr(at + 1);
        screen.uiScale = std::strtof(scale.c_str(), &rest);
        if (at == std::string::npos ||
            !parseSize(item.substr(0, at), screen.width, screen.height) || scale.empty() ||
            *rest != '\0' || !(screen.uiScale >= kMinUiScale) || !(screen.uiScale <= kMaxUiScale)) {
            *error = "expected all or WxH@S,... (e.g. 1280x800@1.5), got '" + item + "'";
            return false;
        }
        out.push_back(screen);
        start = end + 1;
    }
    return true;
}

bool parsePollVotes(const std::string& text, std::vector<std::vector<int>>& rounds) {
    rounds.assign(1, {});
    std::string number;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        const char c = i < text.size() ? text[i] : '/';
        if (c >= '0' && c <= '9' && number.size() < 4) {
            number += c;
            continue;
        }
        if ((c != ',' && c != '/') || number.empty() || std::stoi(number) > 1000) return false;
        rounds.back().push_back(std::stoi(number));
        number.clear();
        if (c == '/' && i < text.size()) rounds.emplace_back();
    }
    return true;
}

std::vector<OutputFile> outputFiles(const Options& o) {
    return {{"--screenshot", &o.screenshot},
            {"--layout-json", &o.layoutJson},
            {"--text-json", &o.textJson},
            {"--audio-wav", &o.audioWav}};
}

ParsedOptions parseOptions(int argc, const char* const* argv) {
    ParsedOptions result;
    Options& o = result.options;
    CLI::App app{"Collision sandbox: the lecture's block collisions, live. Opens a window; with "
                 "no display, or with --screenshot/--record, renders offscreen to PNG files."};
    std::string size, show;
    app.add_option("scene", o.scene, "Scene file, or the name of a shipped scene");
    app.add_option("--screenshot", o.screenshot, "Render offscreen and write this PNG");
    // Counts of frames: rows of the limits table (input_limits.h), checked as sandbox-cli checks
    // its numbers (the same messages; "1e3" is 1000), then handed to CLI11 as a plain integer (a
    // transform).
    auto frameCount = [](const limits::Range& range) {
        return CLI::Validator(
            [range](std::string& text) -> std::string {
                double n = 0.0;
                if (std::string problem = limits::textViolation(text, range, n); !problem.empty())
                    return problem;
                text = std::to_string(static_cast<long long>(n));
                return "";
            },
            "N");
    };
    app.add_option("--frames", o.frames,
                   "Simulate N frames first (with --record: record N), " +
                       limits::describe(limits::kFrames))
        ->transform(frameCount(limits::kFrames));
    app.add_option("--size", size, "Window or image size, WxH (default 1280x720)");
    const std::string showHelp = "Comma-separated: " + showNames();
    app.add_option("--show", show, showHelp);
    CLI::Option* record =
        app.add_option("--record", o.record, "Write N numbered PNGs (and an MP4 with ffmpeg) here");
    CLI::Option* benchmark =
        app.add_option("--benchmark-frames", o.benchmarkFrames,
                       "Offscreen: step and render N frames, print ms per frame (with "
                       "--screenshot: and write the last one), " +
                           limits::describe(limits::kBenchmarkFrames))
            ->transform(frameCount(limits::kBenchmarkFrames))
            ->excludes(record);
    app.add_flag("--benchmark-in-turn", o.benchmarkInTurn,
                 "With --benchmark-frames: each frame worked out, then drawn (not the next "
                 "worked out on a second thread while one is drawn)")
        ->needs(benchmark);
    // A decimal number within the app's range (CLI::Range lets NaN through).
    const limits::Range uiScale{kMinUiScale, kMaxUiScale, ""};
    app.add_option("--ui-scale", o.uiScale, "UI scale (0.75 to 3; e.g. 1.5 on a projector)")
        ->check(CLI::Validator(
            [uiScale](std::string& text) -> std::string {
                double x = 0.0;
                return limits::textViolation(text, uiScale, x);
            },
            "S"));
    app.add_flag("--verbose", o.verbose,
                 "Print to stdout, one line each: every key pressed and what it did, every lesson "
                 "step, setting and toggle changed (pause, method, sliders, the keyboard's owner)");
    // The keys named here come from the key table (input_map.h), so the help cannot drift.
    app.add_flag("--present", o.present,
                 "Start in present mode: only the scene and a one-line caption (" +
                     keyNameOf(Action::TogglePresent) + " toggles)");
    app.add_option("--layout-json", o.layoutJson,
                   "Offscreen: write the scene's, the world's and every window's rectangle in "
                   "image pixels to this JSON file (without --screenshot no image is rendered)");
    app.add_option("--text-json", o.textJson,
                   "Offscreen: write every text drawn in the last frame (its text, rectangle in "
                   "image pixels, line height, window, clipped) to this JSON file (without "
                   "--screenshot no image is rendered)");
    std::string frame;
    app.add_option("--frame", frame,
                   "Start in this frame of reference: world, or com (the view moves with the "
                   "centre of mass, arrows show w = v - u; " +
                       keyNameOf(Action::ToggleFrame) + " toggles)");
    app.add_option("--lesson", o.lesson,
                   "Open a lesson: a shipped lesson's name (lecture3) or a lesson file");
    app.add_option("--step", o.step, "Start the lesson at step N (1 is the first)")
        ->check(CLI::Range(1, 1000000));
    std::string at = "moment";
    app.add_option("--at", at,
                   "Offscreen, with --lesson: setup (the step at t = 0, its question asked) or "
                   "moment (its pause point, the answer shown; the default)")
        ->check(CLI::IsMember({"setup", "moment"}));
    CLI::Option* recordSteps = app.add_option(
        "--record-steps", o.recordSteps,
        "Offscreen: write every lesson step at its setup and its moment here (PNG and JSON)");
    CLI::Option* recordScenes = app.add_option(
        "--record-scenes", o.recordScenes,
        "Offscreen: write every shipped scene, after --frames N frames, with --show's "
        "overlays, here (SCENE.png, SCENE.layout.json, SCENE.text.json)");
    recordScenes->excludes(recordSteps);
    std::string screens;
    app.add_option("--screens", screens,
                   "With --record-steps or --record-scenes: at each of these screen sizes and UI "
                   "scales (all: every classroom screen, or WxH@S,... e.g. "
                   "1280x800@1.5,1024x768@1), each into DIR/WxH_uiS/, the layout and text JSON "
                   "only (nothing rasterised)")
        ->type_name("LIST");
    app.add_option("--theme", o.theme,
                   "dark or light (bright rooms); the window's default is the saved setting")
        ->check(CLI::IsMember({"dark", "light"}));
    app.add_option("--timeline-frame", o.timelineFrame,
                   "Offscreen: after --frames, go back to this frame on the timeline (as its "
                   "slider does): the replay as the overlays show it")
        ->check(CLI::Range(0LL, 10000000LL));
    app.add_option("--audio-wav", o.audioWav,
                   "Offscreen: write what would be heard of the frames simulated (--frames N, or "
                   "--record's) to this WAV file (mono, 16 bit, 44.1 kHz; sound on at full "
                   "volume); alone, nothing is rendered");
    app.add_option("--set", o.sets,
                   "Set a world key or a block's field at the start (repeatable): "
                   "bounciness=0.5, m2.mass=4, blocks[1].velocity=3,0 (docs/edits.md)")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    app.add_option("--edits", o.edits,
                   "Replay an edit log: JSON lines, each an edit, undo or redo with the frame it "
                   "applies at (docs/edits.md); R and Shift+R play it again")
        ->type_name("FILE.jsonl");
    std::string traceUnits, pxPerM, pxOrigin;
    app.add_option("--compare", o.compareTrace,
                   "Open a trace your engine printed (CSV: t, then NAME_x, NAME_y, NAME_vx, "
                   "NAME_vy per block; docs/compare.md) on the scene: its blocks as outlines, the "
                   "timeline at the first difference, the inspector's diagnosis");
    // The trace's units: trace.h's table and rule, shared with sandbox-cli compare.
    CLI::Option* unitsOpt = app.add_option("--trace-units", traceUnits, kTraceUnitsOption.help);
    CLI::Option* pxPerMOpt = app.add_option(kPxPerMOption.flag, pxPerM, kPxPerMOption.help);
    CLI::Option* pxOriginOpt = app.add_option(kPxOriginOption.flag, pxOrigin, kPxOriginOption.help);
    unitsOpt->type_name(kTraceUnitsOption.value);
    pxPerMOpt->type_name(kPxPerMOption.value);
    pxOriginOpt->type_name(kPxOriginOption.value);
    app.add_option("--poll", o.pollAddress,
                   "With a lesson: the class poll on, served on this address of the machine "
                   "(docs/poll.md; A turns it on and off)")
        ->type_name("ADDR");
    std::string pollVotes;
    app.add_option("--poll-votes", pollVotes,
                   "Offscreen, with --poll: votes for each choice as phones would send them, "
                   "e.g. 3,17,4; a second round after a slash (3,17,4/1,22,1)")
        ->type_name("COUNTS");
    app.set_version_flag("--version", "sandbox 0.1");
    try {
        app.parse(argc, argv);
        if (!size.empty() && !parseSize(size, o.width, o.height)) {
            throw CLI::ValidationError("--size", "expected WxH, e.g. 1280x720, got '" + size + "'");
        }
        if (!screens.empty()) {
            if (o.recordSteps.empty() && o.recordScenes.empty())
                throw CLI::ValidationError("--screens", "needs --record-steps or --record-scenes");
            std::string error;
            if (!parseScreens(screens, o.screens, &error))
                throw CLI::ValidationError("--screens", error);
        }
        if (!show.empty()) {
            std::string error;
            if (!parseShowList(show, o.show, &error)) throw CLI::ValidationError("--show", error);
            o.showGiven = true;
        }
        if (!frame.empty()) {
            o.frame = parseViewFrame(frame);
            if (!o.frame)
                throw CLI::ValidationError("--frame", "expected world or com, got '" + frame + "'");
        }
        // The JSON of one frame: the screenshot's, or alone (no image); not of a recording.
        const bool otherOutput =
            o.screenshot.empty() &&
            (!o.record.empty() || !o.recordSteps.empty() || !o.recordScenes.empty() ||
             o.benchmarkFrames > 0 || !o.audioWav.empty());
        if (!o.layoutJson.empty() && otherOutput) {
            throw CLI::ValidationError("--layout-json", "needs --screenshot FILE, or no other "
                                                        "output (then no image is rendered)");
        }
        if (!o.textJson.empty() && otherOutput) {
            throw CLI::ValidationError("--text-json", "needs --screenshot FILE, or no other "
                                                      "output (then no image is rendered)");
        }
        o.atSetup = at == "setup";
        if (!pollVotes.empty()) {
            if (o.pollAddress.empty())
                throw CLI::ValidationError("--poll-votes", "needs --poll ADDR");
            if (!parsePollVotes(pollVotes, o.pollVotes))
                throw CLI::ValidationError("--poll-votes", "expected counts such as 3,17,4 or "
                                                           "3,17,4/1,22,1 (each 0 to 1000), got '" +
                                                               pollVotes + "'");
        }
        if (!o.recordSteps.empty() && o.lesson.empty() && o.scene.empty()) {
            throw CLI::ValidationError("--record-steps", "needs a lesson (--lesson NAME)");
        }
        if (o.timelineFrame > o.frames) {
            throw CLI::ValidationError("--timeline-frame", "must be at most --frames (" +
                                                               std::to_string(o.frames) +
                                                               "): the frames recorded");
        }
        auto given = [](const CLI::Option* option, const std::string& text) {
            return option->count() > 0 ? std::optional<std::string>(text) : std::nullopt;
        };
        if (const auto refused =
                readTraceUnitsOptions({given(unitsOpt, traceUnits), given(pxPerMOpt, pxPerM),
                                       given(pxOriginOpt, pxOrigin)},
                                      "--trace-units", o.traceUnits))
            throw CLI::ValidationError(refused->flag +
                                           (refused->text.empty() ? "" : " " + refused->text),
                                       refused->expected);
        if (!traceUnits.empty() && o.compareTrace.empty())
            throw CLI::ValidationError("--trace-units", "needs --compare TRACE.csv");
        if (!o.record.empty() && o.frames <= 0) {
            throw CLI::ValidationError("--record", "needs --frames N (N > 0)");
        }
        // An output may never overwrite an input it was made from (the input would be lost).
        for (const auto& [flag, output] : outputFiles(o))
            for (const std::string* input : {&o.scene, &o.lesson, &o.compareTrace, &o.edits})
                if (!output->empty() && !input->empty() && sameExistingFile(*output, *input))
                    throw CLI::ValidationError(flag, "'" + *output +
                                                         "' is an input file of this run; the "
                                                         "output may not overwrite it");
    } catch (const CLI::ParseError& e) {
        // --help and --version exit 0; every other error is bad usage: exit 2, as sandbox-cli
        // (CLI11's own codes, e.g. 105, mean nothing to a script), its message printable (it
        // quotes the arguments).
        result.exit = true;
        if (e.get_exit_code() == 0) {
            result.exitCode = app.exit(e, std::cout, std::cerr);
        } else {
            std::cerr << "sandbox: " << printable(e.what(), 4 * kPrintableDefault)
                      << "\nRun with --help for more information.\n";
            result.exitCode = 2;
        }
    }
    return result;
}
