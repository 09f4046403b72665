#include "app_frame.h"
#include "printable.h"

#include "imgui_ext.h"
#include "overlay_window.h"
#include "renderer.h"
#include "screen_text.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

// The arrow keys push: the thrust (on) or the scene's player (player.h).
bool arrowsPush(const App& app) {
    return app.sim.thrust.on || app.sim.scene.player.has_value();
}

void logEvent(const App& app, const std::string& text) {
    if (!app.log.verbose) return;
    std::printf("%s\n", printable(text, kPrintablePath).c_str()); // names come from files
    std::fflush(stdout);
}

// The keyboard to `window` ("": back to the scene), said in the --verbose log when it changes.
void giveKeyboard(App& app, const std::string& window) {
    if (app.ui.keyboardWindow == window) return;
    app.ui.keyboardWindow = window;
    logEvent(app, "keyboard: " + (window.empty() ? std::string("scene") : window));
}

void handleKeys(App& app, const std::vector<KeyPress>& keys) {
    const ImGuiIO& io = ImGui::GetIO();
    // As ImGui took this frame's keys: its navigation on or off (followKeyboard, last frame), its
    // focus ring shown, a text field typed into (a file name, a value: no key is a hotkey then).
    const bool typing = io.WantTextInput;
    const bool navigation = (io.ConfigFlags & ImGuiConfigFlags_NavEnableKeyboard) != 0;
    const bool ring = io.NavActive && io.NavVisible;
    for (const KeyPress& k : keys) {
        const Action action =
            actionForKey(k.key, k.ctrl, k.shift, arrowsPush(app), app.ui.inBrowser);
        const KeyRoute route = routeKey(k.key, k.ctrl, action, typing, navigation, ring);
        if (app.log.verbose) {
            const std::string name = keyName(k.key, k.ctrl, k.shift);
            if (!name.empty())
                logEvent(app,
                         "key " + name + ": " +
                             (route == KeyRoute::Navigation ? std::string("keyboard navigation")
                              : route == KeyRoute::Typing   ? std::string("typing")
                                                            : std::string(actionName(action))));
        }
        if (route != KeyRoute::Table) continue;
        const bool dialog = app.ui.quitDialogOpen || app.ui.saveDialogOpen;
        if (typing && action == Action::Escape && !dialog) {
            // The panel's field undoes the typing and leaves (ImGui's); nothing else closes.
            logEvent(app, "escape: the field left");
            giveKeyboard(app, "");
            continue;
        }
        // A key that acts while a field is typed into leaves the field, with what was typed (as
        // a click elsewhere would); a dialog's Esc closes it.
        if (typing && action != Action::Escape) imgui_ext::stopTyping();
        if (action == Action::LessonDigit) {
            lessonTypeDigit(app.lesson, digitOfKey(k.key));
            if (app.lesson.active()) logEvent(app, "lesson step typed: " + app.lesson.digits);
        } else {
            applyAction(app, action);
        }
    }
}

// After the frame's windows: who has the keyboard now. While a window has it (F6, Tab), a press
// in another window with controls (the panel, an overlay window, Help, a dialog) gives it that
// window; a press in the scene gives it back, and so does the window's going away (present mode,
// Help closed). A press in a window while the scene has the keyboard (a slider dragged, a field
// clicked) leaves it the scene's: the lecture's keys keep working after the mouse has set a value.
// ImGui's keyboard navigation is on only while a window has the keyboard or a dialog is open (and
// never while the arrows push a thrust or a player): the focus ring is never on a control nobody
// picked.
void followKeyboard(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool pressed = ImGui::IsMouseClicked(ImGuiMouseButton_Left) ||
                         ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
    if (pressed && !app.ui.clickedWindow.empty() && app.ui.clickedWindow != "Lesson caption") {
        if (!app.ui.keyboardWindow.empty()) giveKeyboard(app, app.ui.clickedWindow);
    } else if (pressed && !io.WantCaptureMouse)
        giveKeyboard(app, "");
    app.ui.clickedWindow.clear();
    const std::vector<DockedWindow>& shown = app.view.shownWindows;
    if (std::none_of(shown.begin(), shown.end(),
                     [&app](const DockedWindow& w) { return w.name == app.ui.keyboardWindow; }))
        giveKeyboard(app, "");
    const bool dialog = app.ui.quitDialogOpen || app.ui.saveDialogOpen;
    const bool on = (!app.ui.keyboardWindow.empty() || dialog) && !arrowsPush(app);
    ImGuiIO& config = ImGui::GetIO();
    if (on)
        config.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
    else
        config.ConfigFlags &= ~ImGuiConfigFlags_NavEnableKeyboard;
}

// R (Action::Reset) and Shift+R (Action::ResetToFile): in a lesson the step again (from its setup,
// or as written), else a new run (the chosen settings kept, or the file's); the session prints
// the settings the restart changed.
void restart(App& app, Action action) {
    const bool toFile = action == Action::ResetToFile;
    app.sim.restartShowingChanges([&app, action, toFile] {
        if (applyLessonAction(app, action)) {
            const std::string step = std::to_string(app.lesson.current + 1);
            logEvent(app,
                     ((toFile ? "lesson step as written " : "lesson restart ") + step).c_str());
        } else if (toFile) {
            resetToFile(app);
            logEvent(app, "reset to file");
        } else {
            resetScene(app);
            logEvent(app, "reset");
        }
    });
}

} // namespace

void applyAction(App& app, Action action) {
    switch (action) {
    case Action::None:
        break;
    case Action::Reset:
    case Action::ResetToFile:
        restart(app, action);
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
        if (!app.ui.keyboardFocus.empty()) giveKeyboard(app, app.ui.keyboardFocus);
        break;
    case Action::NextWindow:
        app.ui.keyboardFocus = nextWindowForKeyboard(app);
        if (!app.ui.keyboardFocus.empty()) giveKeyboard(app, app.ui.keyboardFocus);
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
        logEvent(app, "fit view");
        break;
    case Action::TogglePresent:
        setPresentMode(app.view, !app.view.presentMode);
        logEvent(app, app.view.presentMode ? "present mode: on" : "present mode: off");
        break;
    case Action::ToggleFullscreen:
        app.ui.fullscreenRequested = true;
        logEvent(app, app.view.fullscreen ? "fullscreen: off" : "fullscreen: on");
        break;
    case Action::ToggleHelp:
        app.ui.helpOpen = !app.ui.helpOpen;
        logEvent(app, app.ui.helpOpen ? "help: on" : "help: off");
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
        const bool keyboard = !app.ui.keyboardWindow.empty();
        const EscapeEffect e = pressEscape(app, keyboard);
        logEvent(app, e == EscapeEffect::CloseDialog       ? "escape: dialog closed"
                      : e == EscapeEffect::CloseHelp       ? "escape: help closed"
                      : e == EscapeEffect::LeavePresent    ? "escape: present mode off"
                      : e == EscapeEffect::LeaveFullscreen ? "escape: fullscreen off"
                      : keyboard                           ? "escape: the keyboard to the scene"
                                                           : "escape: nothing to close");
        giveKeyboard(app, ""); // whatever else it did
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
    case Action::Undo:
    case Action::Redo:
        undoOrRedo(app, action == Action::Undo);
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
        // A step that plays its player's keys itself (a lesson's "input") hands the player over
        // to the keys at the first arrow pressed: from then on the arrows drive it.
        if (app.sim.scene.player && !app.sim.thrust.on && !app.sim.script.empty()) {
            app.sim.script.clear();
            logEvent(app, "player: the arrow keys drive it (the step's own input stops)");
        }
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
    const auto layOut = [&app, &io] {
        planLessonCaption(app); // the bar's height for the step shown (a key may change it)
        updateCamera(app, io.DisplaySize.x, io.DisplaySize.y);
    };
    layOut();
    // Input: the keys pressed (F6 reads the windows the last frame drew), the thrust's arrow keys
    // held (not while typing into a field or moving the keyboard's focus ring), the mouse in the
    // scene.
    handleKeys(app, keys);
    app.view.shownWindows.clear();
    app.view.shownPlots.clear();
    app.view.shownMarks.clear();
    forgetTextRoles();
    const Vec2 held =
        arrowsPush(app) && !io.WantTextInput ? heldThrustDirection(imgui_ext::keyDown) : Vec2{};
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
    drawYieldedAxisNumbers(app);
    if (app.lesson.active()) drawLessonCaption(app); // a lesson's one caption, presenting too
    drawPollWindow(app);
    // The steps are timed only while the panel's Statistics shows their time (drawControlsPanel
    // says so when it draws that section; a closed sheet, presenting or a hidden UI shows none).
    app.sim.stepTimeShown = false;
    if (!app.view.presentMode) {
        if (app.view.uiVisible) drawControlsPanel(app);
        if (app.ui.helpOpen) drawHelpWindow(app);
    }
    drawDialogs(app);
    followKeyboard(app);
    logStateChanges(app);
}

void appPrepareScene(const App& app, SceneRenderer& renderer, int framebufferWidth,
                     int framebufferHeight, SceneFrame& frame, bool measureDrawn) {
    const ImGuiIO& io = ImGui::GetIO();
    SceneView scene;
    scene.world = &app.sim.world();
    scene.camera = &app.view.camera;
    scene.displayWidth = io.DisplaySize.x;
    scene.displayHeight = io.DisplaySize.y;
    scene.framebufferWidth = framebufferWidth;
    scene.framebufferHeight = framebufferHeight;
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
    renderer.prepare(scene, frame, measureDrawn);
}
