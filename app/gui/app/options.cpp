#include "options.h"

#include "app_config.h"
#include "input_limits.h"
#include "printable.h"
#include "safe_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
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
    app.add_option("--benchmark-frames", o.benchmarkFrames,
                   "Offscreen: step and render N frames, print ms per frame (with --screenshot: "
                   "and write the last one), " +
                       limits::describe(limits::kBenchmarkFrames))
        ->transform(frameCount(limits::kBenchmarkFrames))
        ->excludes(record);
    // A decimal number within the app's range (CLI::Range lets NaN through).
    const limits::Range uiScale{kMinUiScale, kMaxUiScale, ""};
    app.add_option("--ui-scale", o.uiScale, "UI scale (0.75 to 3; e.g. 1.5 on a projector)")
        ->check(CLI::Validator(
            [uiScale](std::string& text) -> std::string {
                double x = 0.0;
                return limits::textViolation(text, uiScale, x);
            },
            "S"));
    app.add_flag("--verbose", o.verbose, "Print state changes (pause, method, sliders) to stdout");
    app.add_flag("--present", o.present,
                 "Start in present mode: only the scene and a one-line caption (Tab toggles)");
    app.add_option("--layout-json", o.layoutJson,
                   "Offscreen (with --screenshot): write the scene's, the world's and every "
                   "window's rectangle in image pixels to this JSON file");
    app.add_option("--text-json", o.textJson,
                   "Offscreen (with --screenshot): write every text drawn in the last frame "
                   "(its text, rectangle in image pixels, line height, window, clipped) to this "
                   "JSON file");
    std::string frame;
    app.add_option("--frame", frame,
                   "Start in this frame of reference: world, or com (the view moves with the "
                   "centre of mass, arrows show w = v - u; U toggles)");
    app.add_option("--lesson", o.lesson,
                   "Open a lesson: a shipped lesson's name (lecture3) or a lesson file");
    app.add_option("--step", o.step, "Start the lesson at step N (1 is the first)")
        ->check(CLI::Range(1, 1000000));
    std::string at = "moment";
    app.add_option("--at", at,
                   "Offscreen, with --lesson: setup (the step at t = 0, its question asked) or "
                   "moment (its pause point, the answer shown; the default)")
        ->check(CLI::IsMember({"setup", "moment"}));
    app.add_option("--record-steps", o.recordSteps,
                   "Offscreen: write one PNG per lesson step (after its pause point) here");
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
    std::string traceUnits, pxPerM, pxOrigin;
    app.add_option("--compare", o.compareTrace,
                   "Open a trace your engine printed (CSV: t, then NAME_x, NAME_y, NAME_vx, "
                   "NAME_vy per block; docs/compare.md) on the scene: its blocks as outlines, the "
                   "timeline at the first difference, the inspector's diagnosis");
    app.add_option("--trace-units", traceUnits,
                   "The trace's units: si (m, m/s, y up; the default) or gxp (pixels, y down, "
                   "velocities in pixels per frame; needs --px-per-m)")
        ->check(CLI::IsMember({"si", "gxp"}));
    app.add_option("--px-per-m", pxPerM, "gxp: pixels per metre");
    app.add_option("--px-origin", pxOrigin, "gxp: the pixel X,Y of the world's top-left corner");
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
        if (!o.layoutJson.empty() && o.screenshot.empty()) {
            throw CLI::ValidationError("--layout-json", "needs --screenshot FILE");
        }
        if (!o.textJson.empty() && o.screenshot.empty()) {
            throw CLI::ValidationError("--text-json", "needs --screenshot FILE");
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
        if (!traceUnits.empty()) parseTraceUnits(traceUnits, o.traceUnits.units);
        const bool gxp = o.traceUnits.units == TraceUnits::Gxp;
        if (gxp && pxPerM.empty())
            throw CLI::ValidationError("--trace-units gxp", "needs --px-per-m N");
        if (!gxp && (!pxPerM.empty() || !pxOrigin.empty()))
            throw CLI::ValidationError("--px-per-m and --px-origin", "are for --trace-units gxp");
        if (!pxPerM.empty())
            if (std::string p = parsePxPerM(pxPerM, o.traceUnits.pxPerM); !p.empty())
                throw CLI::ValidationError("--px-per-m", p);
        if (!pxOrigin.empty())
            if (std::string p = parsePxOrigin(pxOrigin, o.traceUnits.originPx); !p.empty())
                throw CLI::ValidationError("--px-origin", p);
        if (!traceUnits.empty() && o.compareTrace.empty())
            throw CLI::ValidationError("--trace-units", "needs --compare TRACE.csv");
        if (!o.record.empty() && o.frames <= 0) {
            throw CLI::ValidationError("--record", "needs --frames N (N > 0)");
        }
        // An output may never overwrite an input it was made from (the input would be lost).
        for (const auto& [flag, output] : outputFiles(o))
            for (const std::string* input : {&o.scene, &o.lesson, &o.compareTrace})
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
