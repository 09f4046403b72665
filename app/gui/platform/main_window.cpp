// sandbox: the window a lecturer opens in class. With no display, or for --screenshot, --record
// and --benchmark-frames, it runs the sibling `sandbox-offscreen` with the same arguments
// (one executable cannot link both libGL and OSMesa).
#include "app_config.h"
#include "app_frame.h"
#include "app_setup.h"
#include "audio_out.h"
#include "frame_worker.h"
#include "imgui_ext.h"
#include "options.h"
#include "prepared_frame.h"
#include "printable.h"
#include "renderer.h"
#include "scene_library.h"
#include "ui_renderer_gl.h"
#include "ui_style.h"
#include "window_glfw.h"

#include <imgui.h>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

int execOffscreen(int argc, char** argv, bool addDefaultScreenshot) {
    const std::string path = executableDirectory() + "/sandbox-offscreen";
    std::vector<std::string> args(argv, argv + argc);
    args[0] = path;
    if (addDefaultScreenshot) {
        args.push_back("--screenshot");
        args.push_back("sandbox-screenshot.png");
    }
    std::vector<char*> cargs;
    for (std::string& a : args) cargs.push_back(a.data());
    cargs.push_back(nullptr);
    std::fflush(stdout);
    std::fflush(stderr);
    execv(path.c_str(), cargs.data());
    std::fprintf(stderr, "sandbox: cannot run %s: %s\n", printable(path, kPrintablePath).c_str(),
                 std::strerror(errno));
    return 1;
}

int runWindow(const Options& options, char** argv, int argc) {
    const std::string configDir = configDirectory();
    std::vector<std::string> settingsWarnings; // a bad settings file never stops the start
    AppConfig config = loadAppConfig(configDir, &settingsWarnings);
    for (const std::string& w : settingsWarnings) std::fprintf(stderr, "sandbox: %s\n", w.c_str());
    App app;
    std::string error;
    if (!setupApp(app, options, config.lastScene, &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        return 1;
    }
    if (!config.lastScene.empty() && !app.ui.messages.error.empty()) // it did not load
        std::fprintf(stderr, "sandbox: %s:%zu: %s\n",
                     printable(configDir + "/settings.txt", kPrintablePath).c_str(),
                     config.lastSceneLine, app.ui.messages.error.c_str());
    if (!settingsWarnings.empty() && app.ui.messages.error.empty())
        app.ui.messages.error = settingsWarnings.front();
    applyStartSettings(app, config, options);
    app.ui.firstLaunch = !config.existed;
    const bool sizeGiven = options.width != 1280 || options.height != 720;
    const int width = sizeGiven ? options.width : config.windowWidth;
    const int height = sizeGiven ? options.height : config.windowHeight;

    std::string iniPath;
    if (!configDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(configDir, ec);
        if (!ec) iniPath = configDir + "/imgui.ini";
    }
    uiCreateContext(iniPath.empty() ? nullptr : iniPath.c_str());
    uiFollowView(app.view, app.ui.touchUi);
    WindowGlfw window;
    if (!windowInit(window, width, height, "Collision sandbox", &error)) {
        uiDestroyContext();
        std::fprintf(stderr, "sandbox: no window: %s; rendering offscreen instead\n",
                     error.c_str());
        return execOffscreen(argc, argv, true);
    }
    SceneRenderer renderer;
    if (!renderer.init(&error)) {
        std::fprintf(stderr, "sandbox: shader error: %s\n", error.c_str());
        app.ui.messages.error = "Shader error: " + error;
    }
    AudioOut audio;
    // The frames pipelined (prepared_frame.h): while the main thread issues frame N's GL calls
    // and shows it, a second thread works out frame N+1 from the input polled before (ImGui's
    // frame, the app's, the scene's geometry: no GL and no GLFW call); the two never touch the
    // app together (the worker's job starts after the poll and is waited for before anything
    // else). A key acts in the frame shown next but one: 16.7 ms later at 60 frames a second.
    // While a text field has the keyboard the frames are worked out here, in turn (ImGui then
    // asks GLFW for the clipboard, which only the main thread may).
    FrameWorker worker;
    PreparedFrame frames[2];
    int next = 0;       // frames[next]: the one worked out next
    bool ready = false; // frames[1 - next] worked out and not drawn yet
    bool shownOnce = false;
    double realSeconds = 0.0;
    const auto workOut = [&](PreparedFrame& frame, const std::vector<KeyPress>& keys, double dt,
                             int fw, int fh) {
        ImGui::NewFrame();
        appFrame(app, keys, dt, true);
        ImGui::Render();
        prepareFrame(app, renderer, fw, fh, frame, true);
    };
    const auto show = [&](const PreparedFrame& frame) {
        drawFrame(renderer, frame);
        windowPresent(window);
        if (!shownOnce && app.log.verbose) {
            std::printf("window ready %dx%d\n", frame.scene.framebufferWidth,
                        frame.scene.framebufferHeight);
            std::fflush(stdout);
        }
        shownOnce = true;
    };
    while (!app.ui.quitRequested && windowNewFrame(window, &realSeconds)) {
        if (window.closeRequested) { // the close button: asks when there are unsaved edits
            window.closeRequested = false;
            requestQuit(app);
            if (app.ui.quitDialogOpen && app.log.verbose)
                std::printf("quit: unsaved edits, asking\n");
        }
        app.view.fullscreen = window.fullscreen;
        for (const std::string& path : windowTakeDroppedFiles(window)) openFile(app, path);
        const std::vector<KeyPress> keys = windowTakeKeyPresses(window);
        int fw = 0, fh = 0;
        windowFramebufferSize(window, &fw, &fh);
        PreparedFrame& worked = frames[next];
        if (imgui_ext::typingAfterFrame()) { // in turn, here
            if (ready) show(frames[1 - next]);
            workOut(worked, keys, realSeconds, fw, fh);
            show(worked);
            ready = false;
        } else if (!ready) { // the pipeline's first frame: shown at the next turn
            workOut(worked, keys, realSeconds, fw, fh);
            ready = true;
            next = 1 - next;
        } else {
            worker.start([&] { workOut(worked, keys, realSeconds, fw, fh); });
            show(frames[1 - next]);
            worker.wait();
            next = 1 - next;
        }
        audio.play(app.sim.sound);
        if (app.ui.fullscreenRequested) {
            windowSetFullscreen(window, !window.fullscreen);
            app.ui.fullscreenRequested = false;
        }
        // Fonts and theme, only what changed; new fonts go to the UI renderer. A frame worked
        // out with the old atlas is shown first, with it.
        if (uiFollowView(app.view, app.ui.touchUi)) {
            if (ready) show(frames[1 - next]);
            ready = false;
            uiRendererFontsChanged();
        }
    }
    // Absolute, so that the next start from another folder finds it.
    std::error_code absoluteError;
    const std::filesystem::path scenePath = app.sim.scenePath;
    config.lastScene =
        scenePath.empty()
            ? std::string()
            : std::filesystem::absolute(scenePath, absoluteError).lexically_normal().string();
    keepSettings(app, config);
    windowSize(window, &config.windowWidth, &config.windowHeight);
    if (!saveAppConfig(configDir, config) && !configDir.empty()) {
        std::fprintf(stderr, "sandbox: cannot save settings in %s\n",
                     printable(configDir, kPrintablePath).c_str());
    }
    renderer.shutdown();
    windowShutdown(window);
    uiDestroyContext();
    if (app.log.verbose) {
        if (app.ui.framesShown > 0 && app.ui.secondsShown > 0.0) {
            std::printf("shown %lld frames, %.2f ms/frame (%.1f frames/s)\n", app.ui.framesShown,
                        app.ui.secondsShown * 1000.0 / static_cast<double>(app.ui.framesShown),
                        static_cast<double>(app.ui.framesShown) / app.ui.secondsShown);
        }
        std::printf("quit\n");
    }
    // An edit log refused on the way (it stopped there; the panel's note said so).
    if (!app.sim.editLogError.empty()) {
        std::fprintf(stderr, "sandbox: %s\n", app.sim.editLogError.c_str());
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const ParsedOptions parsed = parseOptions(argc, argv);
    if (parsed.exit) return parsed.exitCode;
    const Options& options = parsed.options;
    if (wantsOffscreen(options)) return execOffscreen(argc, argv, false);
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::fprintf(stderr, "sandbox: no display (DISPLAY is not set): rendering offscreen to a "
                             "PNG instead\n");
        return execOffscreen(argc, argv, true);
    }
    return runWindow(options, argv, argc);
}
