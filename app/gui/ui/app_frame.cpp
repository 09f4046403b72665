#include "app_frame.h"
#include "printable.h"

#include "overlay_window.h"
#include "renderer.h"

#include <imgui.h>

#include <cstdio>

namespace {

// True while ImGui's keyboard navigation shows its focus ring: the navigation keys are its.
bool navigating() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.NavActive && io.NavVisible;
}

void handleKeys(App& app, const std::vector<KeyPress>& keys) {
    // Typing into a text field (a file name) must not trigger hotkeys; Esc still closes dialogs.
    const bool typing = ImGui::GetIO().WantTextInput;
    const bool keyboardNavigation = navigating();
    for (const KeyPress& k : keys) {
        const Action action = actionForKey(k.key, k.ctrl, k.shift, app.thrust.on);
        if (typing && action != Action::Escape) continue;
        if (keyboardNavigation && !k.ctrl && navigationKey(k.key)) continue;
        if (action == Action::LessonDigit)
            lessonTypeDigit(app, digitOfKey(k.key));
        else
            applyAction(app, action);
    }
}

void logEvent(const App& app, const char* text) {
    if (!app.verbose) return;
    std::printf("%s\n", printable(text, kPrintablePath).c_str()); // names come from files
    std::fflush(stdout);
}

} // namespace

void applyAction(App& app, Action action) {
    switch (action) {
    case Action::None:
        break;
    case Action::Reset:
        if (applyLessonAction(app, action)) { // in a lesson: restart the step
            logEvent(app, ("lesson restart " + std::to_string(app.lesson.current + 1)).c_str());
            break;
        }
        resetScene(app);
        logEvent(app, "reset");
        break;
    case Action::ResetToFile:
        resetToFile(app);
        logEvent(app, "reset to file");
        break;
    case Action::TogglePause:
        app.paused = !app.paused;
        break;
    case Action::ToggleSlowMotion:
        app.slowMotion = !app.slowMotion;
        break;
    case Action::ToggleTrails:
        app.show.trails = !app.show.trails;
        break;
    case Action::ClearTrails:
        app.trails.clear();
        break;
    case Action::CycleMethod:
        cycleMethod(app);
        break;
    case Action::StepOnce:
        app.paused = true;
        stepSimulation(app);
        logEvent(app, "step");
        break;
    case Action::ToggleVectors:
        app.show.vectors = !app.show.vectors;
        break;
    case Action::ToggleFrame:
        setViewFrame(app,
                     app.frame == ViewFrame::World ? ViewFrame::CentreOfMass : ViewFrame::World);
        logEvent(app, app.frame == ViewFrame::World ? "frame: world" : "frame: com");
        break;
    case Action::KeyboardFocus:
        app.ui.keyboardFocus = "Controls";
        if (!app.uiVisible || app.presentMode) app.ui.keyboardFocus.clear();
        break;
    case Action::NextWindow:
        app.ui.keyboardFocus = nextWindowForKeyboard(app);
        break;
    case Action::Navigate: // a row of the Help window: ImGui's navigation does it (no key)
        break;
    case Action::ToggleSound:
        toggleSound(app.sound, app.lesson.active());
        logEvent(app, soundOn(app.sound, app.lesson.active()) ? "sound: on" : "sound: off");
        break;
    case Action::FitView:
        app.autoFit = true;
        app.frameCamera.anchored = false; // the whole world now, followed from here
        break;
    case Action::TogglePresent:
        setPresentMode(app, !app.presentMode);
        logEvent(app, app.presentMode ? "present mode: on" : "present mode: off");
        break;
    case Action::ToggleFullscreen:
        app.fullscreenRequested = true;
        break;
    case Action::ToggleHelp:
        app.helpOpen = !app.helpOpen;
        break;
    case Action::UiScaleUp:
        setUiScale(app, app.uiScale + 0.25f);
        break;
    case Action::UiScaleDown:
        setUiScale(app, app.uiScale - 0.25f);
        break;
    case Action::DeleteSelected:
        deleteSelected(app);
        break;
    case Action::Escape: {
        const EscapeEffect e = pressEscape(app);
        logEvent(app, e == EscapeEffect::CloseDialog       ? "escape: dialog closed"
                      : e == EscapeEffect::CloseHelp       ? "escape: help closed"
                      : e == EscapeEffect::LeavePresent    ? "escape: present mode off"
                      : e == EscapeEffect::LeaveFullscreen ? "escape: fullscreen off"
                                                           : "escape: nothing to close");
        break;
    }
    case Action::Quit:
        requestQuit(app);
        if (app.quitDialogOpen) logEvent(app, "quit: unsaved edits, asking");
        break;
    case Action::Save:
        app.saveDialogOpen = true;
        app.saveDialogPath = suggestedSavePath(app);
        break;
    case Action::LessonNext:
    case Action::LessonPrevious:
    case Action::LessonFirst:
    case Action::LessonLast:
    case Action::LessonJump:
        applyLessonAction(app, action);
        break;
    case Action::LessonDigit: // needs the key: handleKeys
        break;
    case Action::ThrustLeft: // held, not pressed: appFrame reads the keys down
    case Action::ThrustRight:
    case Action::ThrustDown:
    case Action::ThrustUp:
        break;
    }
}

void logStateChanges(App& app) {
    const LoggedState now = snapshotForLog(app);
    if (app.verbose && app.loggedValid) {
        for (const std::string& line : describeChanges(app.logged, now)) {
            std::printf("%s\n", printable(line, kPrintablePath).c_str());
        }
        std::fflush(stdout);
    }
    app.logged = now;
    app.loggedValid = true;
}

void holdKeyTaps(const std::vector<KeyPress>& queued, std::vector<int>& held,
                 const std::function<bool(int key)>& isDown) {
    ImGuiIO& io = ImGui::GetIO();
    constexpr int keyCount = IM_ARRAYSIZE(ImGuiIO::KeysDown);
    const auto valid = [](int key) { return key >= 0 && key < keyCount; };
    for (int key : held)
        if (valid(key)) io.KeysDown[key] = isDown(key);
    held.clear();
    for (const KeyPress& k : queued) {
        if (!valid(k.key) || io.KeysDown[k.key]) continue;
        io.KeysDown[k.key] = true;
        held.push_back(k.key);
    }
}

void appFrame(App& app, const std::vector<KeyPress>& keys, double realSeconds, bool runClock) {
    const ImGuiIO& io = ImGui::GetIO();
    updateCamera(app, io.DisplaySize.x, io.DisplaySize.y);
    handleKeys(app, keys); // F6 reads the windows the last frame drew
    app.shownWindows.clear();
    // Thrust: the arrow keys held now (not while typing into a field).
    const bool typing = io.WantTextInput || navigating();
    app.thrust.direction = app.thrust.on && !typing ? heldThrustDirection([&io](int key) {
        return key >= 0 && key < IM_ARRAYSIZE(io.KeysDown) && io.KeysDown[key];
    })
                                                    : Vec2{};
    handleSceneMouse(app);
    updateCamera(app, io.DisplaySize.x, io.DisplaySize.y); // the UI toggle may have changed it
    if (runClock) {
        noteFrameShown(app, realSeconds);
        advanceSimulation(app, realSeconds);
        // The centre-of-mass frame follows the world as drawn this frame.
        if (app.frame != ViewFrame::World) updateCamera(app, io.DisplaySize.x, io.DisplaySize.y);
    }
    drawSceneDecorations(app);
    drawOverlays(app);
    if (app.lesson.active()) drawLessonCaption(app); // a lesson's one caption, presenting too
    if (!app.presentMode) {
        if (app.uiVisible) drawControlsPanel(app);
        if (app.helpOpen) drawHelpWindow(app);
    }
    drawDialogs(app);
    logStateChanges(app);
}

void appRender(const App& app, SceneRenderer& renderer, int framebufferWidth,
               int framebufferHeight) {
    const ImGuiIO& io = ImGui::GetIO();
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    SceneView view;
    view.world = &app.world;
    view.camera = &app.camera;
    view.displayWidth = io.DisplaySize.x;
    view.displayHeight = io.DisplaySize.y;
    view.selected = app.selected;
    view.theme = &sceneTheme(app.lightTheme);
    view.vectors = app.show.vectors;
    view.frameVelocity = frameVelocity(app.world, app.frame);
    view.thrustBlock = thrustedBlock(app);
    view.thrust = thrustForce(app);
    view.trails = app.show.trails ? &app.trails : nullptr;
    if (app.show.sideBySide && app.methods.running) {
        for (int m = 0; m < static_cast<int>(Method::Count); ++m) {
            const Method method = static_cast<Method>(m);
            if (method == app.world.settings.method) continue;
            view.ghosts.push_back(
                {&app.methods.run(method).world, markColor(methodMark(method), app.lightTheme)});
        }
    }
    // The ghost overlay: a student's blocks at this frame as outlines (docs/compare.md).
    World yours;
    if (app.show.ghost && app.studentTrace.open()) {
        yours.blocks = app.world.blocks;
        if (app.studentTrace.ghostAt(static_cast<std::int64_t>(app.world.frame), yours))
            view.ghosts.push_back({&yours, studentTraceColor()});
    }
    view.blockColors.reserve(app.world.blocks.size());
    for (std::size_t i = 0; i < app.world.blocks.size(); ++i) {
        view.blockColors.push_back(blockDisplayColor(app, static_cast<int>(i)));
    }
    const MouseTool& m = app.mouse;
    if (m.mode == MouseTool::Mode::Flinging && m.block >= 0 &&
        m.block < static_cast<int>(app.world.blocks.size())) {
        view.flingActive = true;
        view.flingFrom = app.world.blocks[static_cast<std::size_t>(m.block)].position;
        view.flingTo = view.flingFrom + (m.cursorWorld - m.pressWorld);
    }
    renderer.draw(view);
}
