#include "app_frame.h"
#include "printable.h"

#include "imgui_ext.h"
#include "overlay_window.h"
#include "renderer.h"
#include "screen_text.h"

#include <imgui.h>

#include <cstdio>

namespace {

// True while ImGui's keyboard navigation shows its focus ring: the navigation keys are its.
bool navigating() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.NavActive && io.NavVisible;
}

// The arrow keys push: the thrust (on) or the scene's player (player.h).
bool arrowsPush(const App& app) {
    return app.sim.thrust.on || app.sim.scene.player.has_value();
}

// While a lesson step's thrust is on (or the scene has a player) the arrow keys are the thrust, so
// ImGui's keyboard navigation (Tab and the arrows) is off; in every other state it is on.
void followThrustForNavigation(const App& app) {
    ImGuiIO& io = ImGui::GetIO();
    if (arrowsPush(app))
        io.ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
    else
        io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
}

void handleKeys(App& app, const std::vector<KeyPress>& keys) {
    // Typing into a text field (a file name) must not trigger hotkeys; Esc still closes dialogs.
    const bool typing = ImGui::GetIO().WantTextInput;
    const bool keyboardNavigation = navigating() && !arrowsPush(app);
    for (const KeyPress& k : keys) {
        const Action action =
            actionForKey(k.key, k.ctrl, k.shift, arrowsPush(app), app.ui.inBrowser);
        if (typing && action != Action::Escape) continue;
        if (keyboardNavigation && !k.ctrl && navigationKey(k.key)) continue;
        if (action == Action::LessonDigit)
            lessonTypeDigit(app.lesson, digitOfKey(k.key));
        else
            applyAction(app, action);
    }
}

void logEvent(const App& app, const char* text) {
    if (!app.log.verbose) return;
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
        if (applyLessonAction(app, action)) { // in a lesson: the step as written
            logEvent(app,
                     ("lesson step as written " + std::to_string(app.lesson.current + 1)).c_str());
            break;
        }
        resetToFile(app);
        logEvent(app, "reset to file");
        break;
    case Action::TogglePause:
        app.sim.paused = !app.sim.paused;
        break;
    case Action::ToggleSlowMotion:
        app.sim.slowMotion = !app.sim.slowMotion;
        break;
    case Action::ToggleTrails:
        app.view.show.trails = !app.view.show.trails;
        break;
    case Action::ClearTrails:
        app.sim.run.trails.clear();
        break;
    case Action::CycleMethod:
        app.sim.cycleMethod();
        break;
    case Action::StepOnce:
        app.sim.paused = true;
        stepSimulation(app);
        logEvent(app, "step");
        break;
    case Action::ToggleVectors:
        app.view.show.vectors = !app.view.show.vectors;
        break;
    case Action::ToggleFrame:
        setViewFrame(app.view, app.view.frame == ViewFrame::World ? ViewFrame::CentreOfMass
                                                                  : ViewFrame::World);
        logEvent(app, app.view.frame == ViewFrame::World ? "frame: world" : "frame: com");
        break;
    case Action::KeyboardFocus:
        app.ui.keyboardFocus = "Controls";
        if (!app.view.uiVisible || app.view.presentMode) app.ui.keyboardFocus.clear();
        break;
    case Action::NextWindow:
        app.ui.keyboardFocus = nextWindowForKeyboard(app);
        break;
    case Action::Navigate: // a row of the Help window: ImGui's navigation does it (no key)
        break;
    case Action::ToggleSound:
        toggleSound(app.sim.sound, app.lesson.active());
        logEvent(app, soundOn(app.sim.sound, app.lesson.active()) ? "sound: on" : "sound: off");
        break;
    case Action::FitView:
        app.view.autoFit = true;
        app.view.frameCamera.anchored = false; // the whole world now, followed from here
        break;
    case Action::TogglePresent:
        setPresentMode(app.view, !app.view.presentMode);
        logEvent(app, app.view.presentMode ? "present mode: on" : "present mode: off");
        break;
    case Action::ToggleFullscreen:
        app.ui.fullscreenRequested = true;
        break;
    case Action::ToggleHelp:
        app.ui.helpOpen = !app.ui.helpOpen;
        break;
    case Action::TogglePoll:
        if (app.poll.on()) {
            stopPoll(app.poll);
            logEvent(app, "poll: off");
        } else if (startPoll(app.poll, app.lesson, app.sim)) {
            logEvent(app, ("poll: " + pollUrl(app.poll)).c_str());
        } else {
            app.ui.messages.error = app.poll.error;
        }
        break;
    case Action::UiScaleUp:
        setUiScale(app.view, app.view.uiScale + 0.25f);
        break;
    case Action::UiScaleDown:
        setUiScale(app.view, app.view.uiScale - 0.25f);
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
        if (app.ui.quitDialogOpen) logEvent(app, "quit: unsaved edits, asking");
        break;
    case Action::Save:
        if (app.ui.inBrowser) { // the browser's download asks where, and never overwrites
            const std::string path = browserDownloadPath(app);
            if (saveCurrentScene(app, path))
                app.ui.messages.note = "Downloaded " + path.substr(path.rfind('/') + 1);
            break;
        }
        app.ui.saveDialogOpen = true;
        app.ui.saveDialogPath = suggestedSavePath(app);
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
    const LoggedState now = snapshotForLog(app.sim, app.view, app.lesson);
    if (app.log.verbose && app.log.lastValid) {
        for (const std::string& line : describeChanges(app.log.last, now)) {
            std::printf("%s\n", printable(line, kPrintablePath).c_str());
        }
        std::fflush(stdout);
    }
    app.log.last = now;
    app.log.lastValid = true;
}

void appFrame(App& app, const std::vector<KeyPress>& keys, double realSeconds, bool runClock) {
    const ImGuiIO& io = ImGui::GetIO();
    const auto layOut = [&app, &io] { updateCamera(app, io.DisplaySize.x, io.DisplaySize.y); };
    layOut();
    // Input: the keys pressed (F6 reads the windows the last frame drew), the thrust's arrow keys
    // held (not while typing into a field or moving the keyboard's focus ring), the mouse in the
    // scene.
    handleKeys(app, keys);
    followThrustForNavigation(app);
    app.view.shownWindows.clear();
    app.view.shownPlots.clear();
    app.view.shownMarks.clear();
    forgetTextRoles();
    const bool typing = io.WantTextInput || (navigating() && !arrowsPush(app));
    const Vec2 held = arrowsPush(app) && !typing ? heldThrustDirection(imgui_ext::keyDown) : Vec2{};
    // With thrust on the arrows push the selected block; else they are the player's keys (a
    // lesson step's script, when it has one, plays them instead: lesson_session.cpp).
    app.sim.thrust.direction = app.sim.thrust.on ? held : Vec2{};
    if (!app.sim.thrust.on && app.sim.script.empty())
        app.sim.playerKeys = {held.x<0.0, held.x> 0.0, held.y > 0.0};
    handleSceneMouse(app);
    layOut(); // the UI toggle may have changed it
    // The simulation: the frames due in this much real time.
    if (runClock) {
        noteFrameShown(app.ui, realSeconds);
        advanceSimulation(app, realSeconds);
        // The centre-of-mass frame follows the world as drawn this frame.
        if (app.view.frame != ViewFrame::World) layOut();
    }
    takeNotice(app);
    followLesson(app.poll, app.lesson, app.sim); // asks, closes, stops with the lesson
    // The UI: the scene's labels, the overlays, the lesson's caption, the panels, the dialogs.
    drawSceneDecorations(app);
    drawOverlays(app);
    if (app.lesson.active()) drawLessonCaption(app); // a lesson's one caption, presenting too
    drawPollWindow(app);
    if (!app.view.presentMode) {
        if (app.view.uiVisible) drawControlsPanel(app);
        if (app.ui.helpOpen) drawHelpWindow(app);
    }
    drawDialogs(app);
    logStateChanges(app);
}

void appRender(const App& app, SceneRenderer& renderer, int framebufferWidth,
               int framebufferHeight) {
    const ImGuiIO& io = ImGui::GetIO();
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    SceneView scene;
    scene.world = &app.sim.world();
    scene.camera = &app.view.camera;
    scene.displayWidth = io.DisplaySize.x;
    scene.displayHeight = io.DisplaySize.y;
    scene.selected = app.sim.selected;
    scene.theme = &sceneTheme(app.view.lightTheme);
    scene.vectors = app.view.show.vectors;
    scene.frameVelocity = frameVelocity(app.sim.world(), app.view.frame);
    scene.thrustBlock = app.sim.pushedBlock(); // the thrust, or the player's push
    scene.thrust = app.sim.pushForce();
    scene.trails = app.view.show.trails ? &app.sim.run.trails : nullptr;
    if (app.view.show.sideBySide && app.sim.run.methods.running) {
        for (int m = 0; m < static_cast<int>(Method::Count); ++m) {
            const Method method = static_cast<Method>(m);
            if (method == app.sim.world().settings.method) continue;
            scene.ghosts.push_back({&app.sim.run.methods.run(method).world,
                                    markColor(methodMark(method), app.view.lightTheme)});
        }
    }
    // The ghost overlay: a student's blocks at this frame as outlines (docs/compare.md).
    World yours;
    if (app.view.show.ghost && app.studentTrace.open()) {
        yours.blocks = app.sim.world().blocks;
        if (app.studentTrace.ghostAt(static_cast<std::int64_t>(app.sim.world().frame), yours))
            scene.ghosts.push_back({&yours, studentTraceColor()});
    }
    scene.blockColors.reserve(app.sim.world().blocks.size());
    for (std::size_t i = 0; i < app.sim.world().blocks.size(); ++i) {
        scene.blockColors.push_back(app.sim.blockDisplayColor(static_cast<int>(i)));
    }
    const MouseTool& m = app.mouse;
    if (m.mode == MouseTool::Mode::Flinging && m.block >= 0 &&
        m.block < static_cast<int>(app.sim.world().blocks.size())) {
        scene.flingActive = true;
        scene.flingFrom = app.sim.world().blocks[static_cast<std::size_t>(m.block)].position;
        scene.flingTo = scene.flingFrom + (m.cursorWorld - m.pressWorld);
    }
    renderer.draw(scene);
}
