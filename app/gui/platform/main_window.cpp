// sandbox: the window a lecturer opens in class. With no display, or for --screenshot, --record
// and --benchmark-frames, it runs the sibling `sandbox-offscreen` with the same arguments
// (one executable cannot link both libGL and OSMesa).
#include "app_config.h"
#include "app_frame.h"
#include "app_setup.h"
#include "audio_out.h"
#include "options.h"
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
    uiRendererPlanFrameBase(renderer); // windows' backgrounds from the frame's clear
    AudioOut audio;
    bool first = true;
    double realSeconds = 0.0;
    while (!app.ui.quitRequested && windowNewFrame(window, &realSeconds)) {
        if (window.closeRequested) { // the close button: asks when there are unsaved edits
            window.closeRequested = false;
            requestQuit(app);
            if (app.ui.quitDialogOpen && app.log.verbose)
                std::printf("quit: unsaved edits, asking\n");
        }
        app.view.fullscreen = window.fullscreen;
        for (const std::string& path : windowTakeDroppedFiles(window)) openFile(app, path);
        ImGui::NewFrame();
        appFrame(app, windowTakeKeyPresses(window), realSeconds, true);
        ImGui::Render();
        int fw = 0, fh = 0;
        windowFramebufferSize(window, &fw, &fh);
        appRender(app, renderer, fw, fh);
        uiRendererRender(ImGui::GetDrawData());
        windowPresent(window);
        audio.play(app.sim.sound);
        if (first && app.log.verbose) {
            std::printf("window ready %dx%d\n", fw, fh);
            std::fflush(stdout);
        }
        first = false;
        if (app.ui.fullscreenRequested) {
            windowSetFullscreen(window, !window.fullscreen);
            app.ui.fullscreenRequested = false;
        }
        // Fonts and theme, only what changed; new fonts go to the UI renderer.
        if (uiFollowView(app.view, app.ui.touchUi)) uiRendererFontsChanged();
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
