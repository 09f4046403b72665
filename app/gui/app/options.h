// The command line shared by `sandbox` and `sandbox-offscreen` (docs/cli.md, public):
//   sandbox [SCENE] [--screenshot FILE] [--frames N] [--size WxH] [--show LIST]
//           [--record DIR] [--benchmark-frames N] [--ui-scale S] [--verbose] [--present]
//           [--layout-json FILE] [--text-json FILE] [--frame world|com] [--theme dark|light]
//           [--timeline-frame N] [--set KEY=VALUE ...] [--edits FILE]
//           [--audio-wav FILE]
//           [--compare TRACE.csv [--trace-units si|gxp --px-per-m N --px-origin X,Y]]
#pragma once

#include "overlays.h"
#include "trace.h"
#include "view.h"
#include "view_frame.h"

#include <optional>
#include <string>
#include <vector>

struct Options {
    std::string scene;      // file path or shipped scene name; "" for the default scene
    std::string screenshot; // PNG to write (offscreen)
    std::string record;     // directory for numbered PNGs (offscreen)
    int frames = 0;         // simulation frames before the screenshot / frames to record
    int width = 1280;
    int height = 720;
    bool showGiven = false;
    ShowSet show;
    int benchmarkFrames = 0;      // offscreen: render this many frames and print ms per frame
    bool benchmarkInTurn = false; // the benchmark's frames worked out and drawn in turn
    float uiScale = 0.0f;         // 0: the saved setting (window) or 1 (offscreen)
    bool verbose = false;         // print state changes (pause, method, sliders...) to stdout
    bool present = false;     // start in present mode: the scene and a caption, no panel or window
    std::string layoutJson;   // offscreen: write the layout (scene, world, windows) here, in pixels
    std::string textJson;     // offscreen: write every text drawn in the last frame here
    std::string lesson;       // --lesson NAME or file (docs/lesson-format.md)
    int step = 0;             // --step N (1-based) of the lesson; 0: the first
    bool atSetup = false;     // offscreen --at setup: the step at t = 0 with its question (else
                              // --at moment, the default: at its pause point with the answer)
    std::string recordSteps;  // offscreen: one PNG per lesson step into this directory
    std::string recordScenes; // offscreen: every shipped scene (with --show) into this directory
    // --screens: --record-steps or --record-scenes at each of these screens and UI scales, JSON
    // only (view.h)
    std::vector<ClassroomScreen> screens;
    std::optional<ViewFrame> frame; // --frame: start in this frame (a lesson's steps choose theirs)
    std::string theme;              // --theme dark|light; "": the saved setting (window) or dark
    long long timelineFrame = -1;   // offscreen: after --frames, back to this frame (the timeline)
    std::string audioWav;           // offscreen: the knocks of the frames simulated, as a WAV file
    // --compare FILE: a trace of the student's engine opened on the scene (docs/compare.md), in
    // --trace-units (si, or gxp with --px-per-m and --px-origin).
    std::string compareTrace;
    TraceUnitsSpec traceUnits;
    // Edits (docs/edits.md): --set KEY=VALUE at the start, in order, then --edits FILE's lines
    // at their frames.
    std::vector<std::string> sets;
    std::string edits;
    // --poll ADDR: the class poll on for the lesson, served on ADDR (docs/poll.md).
    std::string pollAddress;
    // Offscreen --poll-votes A,B,C[/A,B,C...]: votes for each choice as if phones had sent them,
    // one group per round ("Vote again" between two).
    std::vector<std::vector<int>> pollVotes;
};

// The files a run writes, by flag: none may be an input of the run (the scene, the lesson, the
// --compare trace, a lesson's scene file), by any spelling or link.
struct OutputFile {
    const char* flag;
    const std::string* path; // "" when not given
};
std::vector<OutputFile> outputFiles(const Options& o);

// Parses --poll-votes: "3,17,4" or "3,17,4/1,22,1" (each 0..1000); false otherwise.
bool parsePollVotes(const std::string& text, std::vector<std::vector<int>>& rounds);
// Parses "WxH" (each 16..16384); false otherwise.
bool parseSize(const std::string& text, int& width, int& height);
// --screens: "all" (classroomScreens) or "WxH@S,...", e.g. "1280x800@1.5,1024x768@1"; false
// with `error` set when malformed.
bool parseScreens(const std::string& text, std::vector<ClassroomScreen>& out, std::string* error);

struct ParsedOptions {
    Options options;
    bool exit = false; // --help, --version or an error: exit with exitCode
    int exitCode = 0;
};

// Parses the command line; --help output goes to stdout, errors to stderr.
ParsedOptions parseOptions(int argc, const char* const* argv);

// True when the run renders offscreen rather than opening a window.
inline bool wantsOffscreen(const Options& o) {
    return !o.screenshot.empty() || !o.record.empty() || o.benchmarkFrames > 0 ||
           !o.recordSteps.empty() || !o.recordScenes.empty() || !o.audioWav.empty() ||
           !o.layoutJson.empty() || !o.textJson.empty();
}
