#include "offscreen_run.h"

#include "app_config.h"
#include "app_frame.h"
#include "app_setup.h"
#include "frame_worker.h"
#include "imgui_ext.h"
#include "offscreen_osmesa.h"
#include "png_io.h"
#include "prepared_frame.h"
#include "printable.h"
#include "renderer.h"
#include "safe_file.h"
#include "screen_text.h"
#include "ui_renderer_gl.h"
#include "ui_style.h"
#include "wav_io.h"

#include <imgui.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

constexpr double kFrameSeconds = 1.0 / 60.0;
// ImGui settles window sizes and tables over a couple of frames; render these before capturing.
constexpr int kSettleFrames = 3;

// What a run draws into: an OSMesa context and the scene's renderer, or, with `pixels` false
// (--layout-json / --text-json without an image, --screens), nothing: the frame's UI and
// layout are built and read back as JSON, no pixel rasterised.
struct Offscreen {
    bool pixels = true;
    int width = 0, height = 0; // the image's size (its context's, with pixels)
    OffscreenOsmesa context;
    SceneRenderer renderer;
    PreparedFrame frames[2]; // the benchmark's pipeline: the frame drawn and the one worked out
};

// --audio-wav: the knocks of the frames simulated, mixed as OpenAL plays them (audio_out.cpp),
// on a track that starts at the world's time when the simulation starts.
// A recording's cap: 64 MiB of samples (float), 380 s at 44.1 kHz (README, "Memory in long
// runs"). A longer --audio-wav is refused before the run, not allocated.
constexpr std::size_t kAudioMaxBytes = std::size_t{64} << 20;

struct AudioTrack {
    bool wanted = false;
    bool tooLong = false; // over kAudioMaxBytes: refused, nothing allocated
    double start = 0.0;   // s, world time of sample 0
    std::vector<float> samples;
};

AudioTrack startTrack(App& app, const Options& o, int frames) {
    AudioTrack track;
    track.wanted = !o.audioWav.empty();
    if (!track.wanted) return track;
    app.sim.sound.chosen = true; // what would be heard with sound on, at full volume
    app.sim.sound.on = true;
    app.sim.sound.volume = 1.0f;
    app.sim.sound.queue.clear();
    track.start = app.sim.world().time;
    const double seconds =
        frames * app.sim.world().settings.dt + kKnockSeconds; // the last knock ends
    const double samples = std::ceil(seconds * kSampleRate);
    if (samples * sizeof(float) > static_cast<double>(kAudioMaxBytes)) {
        std::fprintf(stderr,
                     "sandbox: --audio-wav: %.6g s of sound is more than a recording may hold "
                     "(64 MiB: %.6g s at %d Hz); simulate fewer frames\n",
                     seconds, static_cast<double>(kAudioMaxBytes / sizeof(float)) / kSampleRate,
                     kSampleRate);
        track.tooLong = true;
        return track;
    }
    track.samples.assign(static_cast<std::size_t>(samples), 0.0f);
    return track;
}

// One simulation frame, its knocks mixed into the track.
void simulateFrame(App& app, AudioTrack& track) {
    stepSimulation(app);
    for (const Knock& k : app.sim.sound.queue) mixKnock(track.samples, track.start, k, 1.0f);
    app.sim.sound.queue.clear();
}

int writeTrack(const AudioTrack& track, const Options& o) {
    if (!track.wanted) return 0;
    std::string error;
    if (!writeWav(o.audioWav, track.samples, kSampleRate, &error)) {
        std::fprintf(stderr, "sandbox: %s\n", printable(error, kPrintablePath).c_str());
        return 1;
    }
    std::printf("%s\n", printable(o.audioWav, kPrintablePath).c_str());
    return 0;
}

// A frame as the window shows it, worked out and drawn in turn (screenshots, recordings).
void renderFrame(App& app, Offscreen& off) {
    if (off.pixels)
        offscreenNewFrame(off.context, kFrameSeconds);
    else // the frame's input as offscreenNewFrame gives it, and no renderer
        offscreenFrameInput(off.width, off.height, kFrameSeconds);
    ImGui::NewFrame();
    appFrame(app, {}, kFrameSeconds, false);
    ImGui::Render();
    if (!off.pixels) return;
    prepareFrame(app, off.renderer, off.context.width, off.context.height, off.frames[0], false);
    drawFrame(off.renderer, off.frames[0]);
    offscreenFinish(off.context);
}

bool writeFrame(const Offscreen& off, const std::string& path) {
    std::string error;
    if (!writePng(path, offscreenPixelsTopDown(off.context), off.context.width, off.context.height,
                  &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        return false;
    }
    return true;
}

bool onPath(const char* program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = dirs.find(':', start);
        const std::string dir = dirs.substr(start, end == std::string::npos ? end : end - start);
        if (!dir.empty() && access((dir + "/" + program).c_str(), X_OK) == 0) return true;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return false;
}

// Runs a program with arguments (no shell) and waits; true when it exits 0.
bool runProgram(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) {
        execvp(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Writes `text` to `path` through a temporary file renamed over it (safe_file.h): a failed write
// names the file and leaves what was there.
bool writeText(const std::string& path, const std::string& text) {
    std::string error;
    if (!writeFileSafely(path, text, &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        return false;
    }
    return true;
}

// The layout of the last frame (--layout-json, docs/cli.md): the scene's rectangle, the world's
// bounds as drawn, every window drawn, every block as drawn (by its name) and every plot, in
// image pixels.
bool writeLayoutJson(const App& app, const std::string& path) {
    const Camera& camera = app.view.camera;
    std::vector<DockedWindow> blocks;
    const std::vector<Block>& world = app.sim.world().blocks;
    for (std::size_t i = 0; i < world.size(); ++i) {
        const Bounds box{world[i].position - world[i].size * 0.5,
                         world[i].position + world[i].size * 0.5};
        blocks.push_back(
            {app.sim.blockDisplayName(static_cast<int>(i)), worldRectOnScreen(camera, box)});
    }
    std::vector<DockedWindow> sideways;
    for (const imgui_ext::SidewaysScroll& w : imgui_ext::sidewaysScrolls())
        sideways.push_back({w.window, {w.min.x, w.min.y, w.max.x - w.min.x, w.max.y - w.min.y}});
    std::vector<DockedWindow> folded;
    for (const DockTabs& t : app.view.layout.tabs)
        for (const std::string& name : t.names)
            if (name != t.shown) folded.push_back({name, t.rect});
    return writeText(
        path, layoutJson(camera.viewport(), worldRectOnScreen(camera, app.sim.world().bounds),
                         app.view.shownWindows, blocks, app.view.shownPlots, app.view.shownMarks,
                         app.view.shownMagnified, sideways, folded));
}

// The texts of the frame rendered last (--text-json, screen_text.h).
bool writeTextJson(const std::string& path) {
    return writeText(path,
                     screenTextJson(readScreenText(*ImGui::GetDrawData(), *ImGui::GetIO().Fonts)));
}

// Writes the frame rendered last to --screenshot and prints where it is.
int writeScreenshot(Offscreen& off, const Options& o) {
    if (!writeFrame(off, o.screenshot)) return 1;
    std::error_code ec; // print where the PNG is, as an absolute path when it can be had
    const std::filesystem::path where = std::filesystem::absolute(o.screenshot, ec);
    std::printf("%s\n", printable(ec ? o.screenshot : where.string(), kPrintablePath).c_str());
    return 0;
}

int screenshot(App& app, Offscreen& off, const Options& o) {
    // The step's moment (its pause point, the answer shown), or with --at setup the step as it
    // opens: t = 0, the question asked.
    // The class poll's votes (--poll-votes), as phones would send them: a round per group.
    for (std::size_t r = 0; r < o.pollVotes.size(); ++r) {
        if (r > 0) {
            closePollVote(app.poll);
            pollVoteAgain(app.poll);
        }
        castDemoVotes(app.poll, o.pollVotes[r]);
    }
    if (app.lesson.active() && !o.atSetup) lessonShowPausePoint(app);
    // --frames N simulates N frames, as if P had been pressed (the badge then shows no PAUSED).
    AudioTrack track = startTrack(app, o, o.frames);
    if (track.tooLong) return 1;
    for (int i = 0; i < o.frames; ++i) simulateFrame(app, track);
    if (writeTrack(track, o) != 0) return 1;
    if (o.frames > 0) app.sim.paused = false;
    if (o.timelineFrame >= 0) { // the timeline's slider, dragged back: paused there, replaying
        scrubTo(app, static_cast<std::uint64_t>(o.timelineFrame));
        app.sim.paused = true;
    }
    if (app.view.show.cost)
        app.sim.cost.runSweepNow(quickTradeoffSweep(app.shipped.scenesDir)); // the chart
    for (int i = 0; i < kSettleFrames; ++i) renderFrame(app, off);
    const int code = off.pixels ? writeScreenshot(off, o) : 0;
    if (code != 0) return code;
    if (!o.layoutJson.empty() && !writeLayoutJson(app, o.layoutJson)) return 1;
    if (!o.textJson.empty() && !writeTextJson(o.textJson)) return 1;
    return 0;
}

// Creates `dir` (and its parents); says why on stderr when it cannot.
bool makeDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "sandbox: cannot create %s: %s\n",
                     printable(dir, kPrintablePath).c_str(), ec.message().c_str());
        return false;
    }
    return true;
}

int record(App& app, Offscreen& off, const Options& o) {
    if (!makeDirectory(o.record)) return 1;
    for (int i = 0; i < kSettleFrames - 1; ++i) renderFrame(app, off);
    app.sim.paused = false; // a recording runs the scene
    char name[32];
    AudioTrack track = startTrack(app, o, o.frames);
    if (track.tooLong) return 1;
    for (int i = 0; i < o.frames; ++i) {
        simulateFrame(app, track);
        renderFrame(app, off);
        std::snprintf(name, sizeof name, "/frame_%05d.png", i);
        if (!writeFrame(off, o.record + name)) return 1;
    }
    std::printf("wrote %d frames to %s\n", o.frames, printable(o.record, kPrintablePath).c_str());
    if (writeTrack(track, o) != 0) return 1;
    if (!onPath("ffmpeg")) {
        std::printf("ffmpeg not found: no video made (install ffmpeg for an MP4)\n");
        return 0;
    }
    const std::string video = o.record + "/recording.mp4";
    const bool ok =
        runProgram({"ffmpeg", "-y", "-loglevel", "error", "-framerate", "60", "-i",
                    o.record + "/frame_%05d.png", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v",
                    "libx264", "-pix_fmt", "yuv420p", video});
    if (!ok) {
        std::fprintf(stderr, "sandbox: ffmpeg failed; the PNG frames are in %s\n",
                     printable(o.record, kPrintablePath).c_str());
        return 1;
    }
    std::printf("%s\n", printable(video, kPrintablePath).c_str());
    return 0;
}

// The frame rendered last as three files: BASE.png (with pixels), BASE.layout.json
// (--layout-json) and BASE.text.json (--text-json).
bool writeFrameFiles(const App& app, const Offscreen& off, const std::string& base) {
    return (!off.pixels || writeFrame(off, base + ".png")) &&
           writeLayoutJson(app, base + ".layout.json") && writeTextJson(base + ".text.json");
}

// The windows folded behind tabs in the frame rendered last (DockTabs), each brought to the front
// in turn and drawn: their texts into BASE.folded.text.json (as --text-json writes them) and the
// parts of them that scroll sideways into BASE.folded.layout.json ("sideways"); no window is
// folded: both empty. The windows in front are as they were after.
bool writeFoldedFiles(App& app, Offscreen& off, const std::string& base) {
    std::vector<std::string> folded;
    for (const DockTabs& t : app.view.layout.tabs)
        for (const std::string& name : t.names)
            if (name != t.shown) folded.push_back(name);
    const std::vector<std::string> front = app.view.frontWindows;
    std::vector<ScreenText> texts;
    std::vector<DockedWindow> sideways;
    for (const std::string& name : folded) {
        bringToFront(app.view, name);
        for (int k = 0; k < kSettleFrames; ++k) renderFrame(app, off);
        for (ScreenText& t : readScreenText(*ImGui::GetDrawData(), *ImGui::GetIO().Fonts))
            if (t.window == name) texts.push_back(std::move(t));
        for (const imgui_ext::SidewaysScroll& w : imgui_ext::sidewaysScrolls())
            if (w.window == name)
                sideways.push_back(
                    {w.window, {w.min.x, w.min.y, w.max.x - w.min.x, w.max.y - w.min.y}});
    }
    app.view.frontWindows = front;
    return writeText(base + ".folded.text.json", screenTextJson(texts)) &&
           writeText(base + ".folded.layout.json",
                     layoutJson({}, {}, {}, {}, {}, {}, {}, sideways));
}

// Every lesson step twice into `dir`: at its setup (t = 0, the question asked: DIR/step_NN_setup.*)
// and at its moment (its pause point, the answer shown: DIR/step_NN_moment.*), each with its
// layout and its texts (writeFrameFiles).
bool recordStepsInto(App& app, Offscreen& off, const std::string& dir) {
    if (!makeDirectory(dir)) return false;
    char name[32];
    for (std::size_t i = 0; i < app.lesson.lesson->steps.size(); ++i) {
        enterStep(app, i);
        for (const char* at : {"setup", "moment"}) {
            if (std::string(at) == "moment") lessonShowPausePoint(app);
            if (app.view.show.cost)
                app.sim.cost.runSweepNow(quickTradeoffSweep(app.shipped.scenesDir));
            for (int k = 0; k < kSettleFrames; ++k) renderFrame(app, off);
            std::snprintf(name, sizeof name, "/step_%02zu_%s", i + 1, at);
            if (!writeFrameFiles(app, off, dir + name)) return false;
        }
    }
    return true;
}

// At `screen`: the image's size, the UI scale, and the fonts and style for them.
void useScreen(App& app, Offscreen& off, const ClassroomScreen& screen) {
    off.width = screen.width;
    off.height = screen.height;
    ImGui::GetIO().DisplaySize =
        ImVec2(static_cast<float>(screen.width), static_cast<float>(screen.height));
    setUiScale(app.view, screen.uiScale);
    uiFollowView(app.view, app.ui.touchUi); // the fonts and style for its height and scale
}

// A handout that the lesson sweep (ctest) also reads: every step's setup and moment as PNGs with
// their JSON (recordStepsInto); with --screens, at each of those screens and UI scales
// (--screens all: classroomScreens), each into DIR/WxH_uiS/, as JSON only.
int recordSteps(App& app, Offscreen& off, const Options& o) {
    if (!makeDirectory(o.recordSteps)) return 1;
    if (!app.lesson.active()) {
        std::fprintf(stderr, "sandbox: --record-steps needs a lesson\n");
        return 1;
    }
    const std::size_t steps = app.lesson.lesson->steps.size();
    if (o.screens.empty()) {
        if (!recordStepsInto(app, off, o.recordSteps)) return 1;
        std::printf("wrote %zu steps to %s\n", steps,
                    printable(o.recordSteps, kPrintablePath).c_str());
        return 0;
    }
    int screens = 0;
    for (const ClassroomScreen& screen : o.screens) {
        useScreen(app, off, screen);
        if (!recordStepsInto(app, off, o.recordSteps + "/" + screen.name())) return 1;
        ++screens;
    }
    std::printf("wrote %zu steps at %d screens to %s\n", steps, screens,
                printable(o.recordSteps, kPrintablePath).c_str());
    return 0;
}

// Every shipped scene after `frames` frames (--frames; 0: as it opens), with the overlays --show
// chose, into `dir`: DIR/SCENE.* (writeFrameFiles; SCENE the file's name without .json).
bool recordScenesInto(App& app, Offscreen& off, const std::string& dir, int frames) {
    if (!makeDirectory(dir)) return false;
    for (const SceneEntry& scene : app.shipped.scenes) {
        if (!loadScene(app, scene.path)) {
            std::fprintf(stderr, "sandbox: %s\n", app.ui.messages.error.c_str());
            return false;
        }
        for (int i = 0; i < frames; ++i) stepSimulation(app);
        if (frames > 0) app.sim.paused = false; // as in screenshot(): the run going on
        for (int k = 0; k < kSettleFrames; ++k) renderFrame(app, off);
        const std::string name = std::filesystem::path(scene.path).stem().string();
        if (!writeFrameFiles(app, off, dir + "/" + name)) return false;
        if (!writeFoldedFiles(app, off, dir + "/" + name)) return false;
    }
    return true;
}

// Every shipped scene with the overlays of --show (the screen checks of issue 39 read them):
// as PNGs with their JSON, or with --screens at each of those screens, JSON only, each into
// DIR/WxH_uiS/.
int recordScenes(App& app, Offscreen& off, const Options& o) {
    if (app.view.show.cost) // the chart: one sweep for every scene (it runs the shipped ones)
        app.sim.cost.runSweepNow(quickTradeoffSweep(app.shipped.scenesDir));
    if (o.screens.empty()) {
        if (!recordScenesInto(app, off, o.recordScenes, o.frames)) return 1;
    } else {
        for (const ClassroomScreen& screen : o.screens) {
            useScreen(app, off, screen);
            if (!recordScenesInto(app, off, o.recordScenes + "/" + screen.name(), o.frames))
                return 1;
        }
    }
    std::printf("wrote %zu scenes at %zu screens to %s\n", app.shipped.scenes.size(),
                std::max<std::size_t>(o.screens.size(), 1),
                printable(o.recordScenes, kPrintablePath).c_str());
    return 0;
}

// The process's minor page faults so far (getrusage): memory faulted in.
long minorPageFaults() {
    rusage usage{};
    return getrusage(RUSAGE_SELF, &usage) == 0 ? usage.ru_minflt : 0;
}

// The benchmark's frames as the window's loop gives them (prepared_frame.h): frame N+1 worked
// out on a second thread (the simulation's step, the UI built, the frame prepared) while the
// main thread issues frame N's GL calls and waits for its pixels; --benchmark-in-turn: one
// after the other, on the main thread. Where the time goes, ms summed
// over the frames: the frame worked out (on the worker but for the first), the scene's GL calls,
// ImGui's, the wait for the pixels (llvmpipe rasterises there, on its own threads), and the
// wait for the next frame to be worked out.
struct FrameTimes {
    double simulation = 0.0, prepared = 0.0, scene = 0.0, uiDraw = 0.0, finish = 0.0,
           preparedWait = 0.0;
};

int benchmark(App& app, Offscreen& off, const Options& o) {
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point& t) {
        const Clock::time_point now = Clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - t).count();
        t = now;
        return ms;
    };
    for (int i = 0; i < kSettleFrames; ++i) renderFrame(app, off); // shaders compile here
    FrameTimes times;
    // No GL call: the worker's job (for frame 0, the main thread's).
    const auto workOut = [&](PreparedFrame& frame) {
        Clock::time_point t = Clock::now();
        stepSimulation(app);
        times.simulation += since(t);
        offscreenFrameInput(off.context.width, off.context.height, kFrameSeconds);
        ImGui::NewFrame();
        appFrame(app, {}, kFrameSeconds, false);
        ImGui::Render();
        prepareFrame(app, off.renderer, off.context.width, off.context.height, frame, true);
        times.prepared += since(t);
    };
    FrameWorker worker;
    const long faultsBefore = minorPageFaults();
    const auto start = Clock::now();
    uiRendererNewFrame(); // (the fonts are uploaded: settled)
    workOut(off.frames[0]);
    for (int i = 0; i < o.benchmarkFrames; ++i) {
        const PreparedFrame& frame = off.frames[i % 2];
        // The next frame is worked out after the last one too, as in the window (its loop has
        // one in flight): the last frame is drawn while the worker works, as every other.
        if (!o.benchmarkInTurn) worker.start([&] { workOut(off.frames[(i + 1) % 2]); });
        Clock::time_point t = Clock::now();
        drawFrameScene(off.renderer, frame); // drawFrame's two parts, timed apart
        times.scene += since(t);
        drawFrameUi(frame);
        times.uiDraw += since(t);
        offscreenFinish(off.context);
        times.finish += since(t);
        worker.wait();
        times.preparedWait += since(t);
        if (o.benchmarkInTurn) workOut(off.frames[(i + 1) % 2]);
    }
    const double totalMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const double n = o.benchmarkFrames;
    const double perFrame = totalMs / n;
    std::printf("benchmark: %d frames, %dx%d, %zu blocks, %s\n", o.benchmarkFrames,
                off.context.width, off.context.height, app.sim.world().blocks.size(),
                offscreenGlDescription().c_str());
    std::printf("  %.3f ms/frame (%.1f frames/s); simulation %.3f ms/frame, drawing %.3f "
                "ms/frame\n",
                perFrame, 1000.0 / perFrame, times.simulation / n, perFrame - times.simulation / n);
    const double faults = static_cast<double>(minorPageFaults() - faultsBefore) / n;
    std::printf("  drawing: worked out %.3f ms (UI built, scene's geometry; %s), scene drawn "
                "%.3f ms, UI drawn %.3f ms, pixels waited for %.3f ms, next frame waited for "
                "%.3f ms\n",
                (times.prepared - times.simulation) / n,
                o.benchmarkInTurn ? "in turn" : "on a second thread", times.scene / n,
                times.uiDraw / n, times.finish / n, times.preparedWait / n);
    std::printf("  memory: %.1f page faults a frame (memory given back and taken again)\n", faults);
    // With --screenshot too: the last frame benchmarked.
    return o.screenshot.empty() ? 0 : writeScreenshot(off, o);
}

// A lesson's scene files are inputs of the run too (the scene, the lesson and the --compare
// trace are refused by parseOptions): the message for an output that is one, or "".
std::string outputOverLessonScene(const App& app, const Options& o) {
    if (!app.lesson.active()) return "";
    for (const auto& [flag, output] : outputFiles(o))
        for (const LessonStep& step : app.lesson.lesson->steps)
            if (!output->empty() && !step.sceneSource.empty() &&
                sameExistingFile(*output, step.sceneSource))
                return std::string(flag) + ": '" + printable(*output) +
                       "' is a scene file of the lesson, an input of this run; the output may "
                       "not overwrite it";
    return "";
}

// A line of --edits refused on the way (the log stopped there): said on stderr.
bool refusedEdits(const App& app) {
    if (app.sim.editLogError.empty()) return false;
    std::fprintf(stderr, "sandbox: %s\n", app.sim.editLogError.c_str());
    return true;
}

} // namespace

int runOffscreen(const Options& options) {
    Options o = options;
    if (o.screenshot.empty() && o.record.empty() && o.benchmarkFrames <= 0 &&
        o.recordSteps.empty() && o.recordScenes.empty() && o.audioWav.empty() &&
        o.layoutJson.empty() && o.textJson.empty()) {
        o.screenshot = "sandbox-screenshot.png";
    }
    App app;
    std::string error;
    if (!setupApp(app, o, "", &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        return 1;
    }
    if (const std::string clash = outputOverLessonScene(app, o); !clash.empty()) {
        std::fprintf(stderr, "sandbox: %s\n", clash.c_str()); // bad usage, as in parseOptions
        return 2;
    }
    if (o.screenshot.empty() && o.record.empty() && o.benchmarkFrames <= 0 &&
        o.recordSteps.empty() && o.recordScenes.empty() && o.layoutJson.empty() &&
        o.textJson.empty()) { // --audio-wav alone: simulate and listen, draw nothing
        if (app.lesson.active()) lessonShowPausePoint(app);
        AudioTrack track = startTrack(app, o, o.frames);
        if (track.tooLong) return 1;
        for (int i = 0; i < o.frames; ++i) simulateFrame(app, track);
        return refusedEdits(app) ? 1 : writeTrack(track, o);
    }
    applyStartSettings(app, AppConfig{}, o); // the defaults: an image never depends on a file
    uiCreateContext(nullptr);
    // The image's size before the fonts: the classroom's are baked for its height.
    ImGui::GetIO().DisplaySize = ImVec2(static_cast<float>(o.width), static_cast<float>(o.height));
    uiFollowView(app.view, app.ui.touchUi);
    Offscreen off;
    off.width = o.width;
    off.height = o.height;
    // No image asked for (the JSON alone, or every size's): nothing is rasterised.
    off.pixels =
        o.screens.empty() && (!o.screenshot.empty() || !o.record.empty() || o.benchmarkFrames > 0 ||
                              !o.recordSteps.empty() || !o.recordScenes.empty());
    if (!off.pixels) {
        ImGui::GetIO().Fonts->Build(); // ImGui lays text out with the atlas (never uploaded)
        const int code = !o.recordSteps.empty()    ? recordSteps(app, off, o)
                         : !o.recordScenes.empty() ? recordScenes(app, off, o)
                                                   : screenshot(app, off, o);
        uiDestroyContext();
        return code;
    }
    if (!offscreenInit(off.context, o.width, o.height, &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        uiDestroyContext();
        return 1;
    }
    const bool shadersOk = off.renderer.init(&error);
    if (!shadersOk) {
        // Keep going: the panels still render and the picture shows what is missing; the exit
        // code says it failed.
        std::fprintf(stderr, "sandbox: shader error: %s\n", error.c_str());
        app.ui.messages.error = "Shader error: " + error;
    }
    int code = 0;
    if (o.benchmarkFrames > 0)
        code = benchmark(app, off, o);
    else if (!o.recordSteps.empty())
        code = recordSteps(app, off, o);
    else if (!o.recordScenes.empty())
        code = recordScenes(app, off, o);
    else if (!o.record.empty())
        code = record(app, off, o);
    else
        code = screenshot(app, off, o);
    off.renderer.shutdown();
    offscreenShutdown(off.context);
    uiDestroyContext();
    if (refusedEdits(app)) return 1;
    return shadersOk ? code : 1;
}
