#include "app.h"

#include "safe_file.h"
#include "save_naming.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string workingDirectory() {
    std::error_code ec;
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    return ec ? std::string() : cwd.string();
}

// `path` made absolute against the working directory: the settings remember it, and it must
// work from any directory.
std::string absolutePath(const std::string& path) {
    const std::string cwd = workingDirectory();
    return cwd.empty() ? path : absoluteScenePath(path, cwd);
}

// A new run started: the mouse lets go of what it held, the view follows from the start.
void startedRun(App& app) {
    app.mouse = MouseTool{};
    followNewRun(app.view, app.sim.world());
}

// After a lesson action: a step entered is a new run, without a refused value of the last one.
void afterLessonAction(App& app) {
    app.ui.typedWarning.clear();
    app.mouse = MouseTool{};
}

} // namespace

void setScene(App& app, const Scene& scene, const std::string& path) {
    app.sim.setScene(scene, path);
    showNewScene(app.view, scene);
    app.ui.typedWarning.clear();
    closeTrace(app); // compared with another scene
    startedRun(app);
}

bool loadScene(App& app, const std::string& path) {
    const SceneResult result = loadSceneFile(path);
    if (!result.scene) {
        app.ui.messages.error = result.error.text();
        return false;
    }
    closeLesson(app);
    setScene(app, *result.scene, absolutePath(path));
    app.ui.messages.clear();
    return true;
}

void resetScene(App& app) {
    app.sim.reset();
    startedRun(app);
}

bool openTrace(App& app, const std::string& path) {
    if (const auto error = openStudentTrace(app.studentTrace, path, app.sim.scene,
                                            app.sim.world().settings, app.studentTrace.units)) {
        app.ui.messages.error = *error;
        return false;
    }
    showOpenedTrace(app);
    return true;
}

void showOpenedTrace(App& app) {
    app.ui.messages.error.clear();
    app.ui.tracePath = app.studentTrace.path;
    // The reference runs from the scene's start, without the Tips' mistakes.
    app.sim.applySettings(app.studentTrace.comparison->reference);
    resetScene(app);
    app.view.show.ghost = app.view.show.timeline = app.view.show.inspector = true;
    goToFirstDifference(app);
    app.ui.messages.note = "Your trace: " + studentTraceSummary(app.studentTrace) + ".";
}

bool compareTraceAgain(App& app) {
    if (!app.studentTrace.open()) return false;
    return openTrace(app, app.studentTrace.path);
}

bool goToFirstDifference(App& app) {
    const std::int64_t frame = app.studentTrace.firstDifference();
    if (frame < 0) return false;
    const auto target = static_cast<std::uint64_t>(frame);
    app.sim.paused = true;
    if (!app.sim.history.empty() && target >= app.sim.history.firstFrame() &&
        target <= app.sim.history.lastFrame())
        return scrubTo(app, target);
    if (app.sim.world().frame > target) resetScene(app);
    while (app.sim.world().frame < target) stepSimulation(app);
    return true;
}

void closeTrace(App& app) {
    const TraceUnitsSpec units = app.studentTrace.units; // the section's choice stays
    app.studentTrace = StudentTrace{};
    app.studentTrace.units = units;
}

bool openFile(App& app, const std::string& path) {
    return isTraceFile(path) ? openTrace(app, path) : loadScene(app, path);
}

void resetToFile(App& app) {
    app.sim.resetToFile();
    startedRun(app);
}

FrameOutcome stepSimulation(App& app) {
    app.sim.inLesson = app.lesson.active();
    if (!lessonBeforeFrames(app.lesson, app.sim, app.view)) return {}; // at its moment at once
    return app.sim.step(lessonRunsSideBySide(app.lesson, app.view));
}

int advanceSimulation(App& app, double realSeconds) {
    if (app.mouse.holdsSimulation()) { // the simulation waits while a block is held
        app.sim.clock.reset();
        return 0;
    }
    app.sim.inLesson = app.lesson.active();
    if (!app.sim.paused && !lessonBeforeFrames(app.lesson, app.sim, app.view)) return 0;
    const int frames = app.sim.advance(realSeconds, lessonRunsSideBySide(app.lesson, app.view));
    if (app.lesson.active()) lessonAfterFrames(app.lesson, app.sim, app.view); // its moment
    return frames;
}

bool scrubTo(App& app, std::uint64_t frame) {
    if (!app.sim.scrubTo(frame)) return false;
    app.ui.inspectorPicked = 0;
    app.mouse = MouseTool{};
    return true;
}

void deleteSelected(App& app) {
    app.sim.deleteSelected();
    app.mouse = MouseTool{};
}

void undoOrRedo(App& app, bool undo) {
    app.mouse = MouseTool{};
    if (undo)
        app.sim.undo();
    else
        app.sim.redo();
}

void updateCamera(App& app, double displayWidth, double displayHeight) {
    app.view.touch = app.ui.touchUi;
    updateCamera(app.view, app.sim.world(), app.lesson.active(), displayWidth, displayHeight);
}

void takeNotice(App& app) {
    if (app.sim.notice.empty()) return;
    app.ui.messages.note = app.sim.notice;
    app.sim.notice.clear();
}

void noteFrameShown(UiState& ui, double realSeconds) {
    if (!(realSeconds > 0.0)) return;
    const double ms = realSeconds * 1000.0;
    ui.frameMsSmoothed =
        ui.framesShown == 0 ? ms : ui.frameMsSmoothed + (ms - ui.frameMsSmoothed) / 30.0;
    ++ui.framesShown;
    ui.secondsShown += realSeconds;
}

void requestQuit(App& app) {
    if (app.ui.quitDialogOpen || !app.sim.unsavedEdits()) {
        app.ui.quitRequested = true;
        return;
    }
    app.ui.quitDialogOpen = true;
}

EscapeEffect pressEscape(App& app, bool keyboardBack) {
    UiState& ui = app.ui;
    const EscapeEffect e = escapeEffect(ui.quitDialogOpen || ui.saveDialogOpen, ui.helpOpen,
                                        app.view.presentMode, app.view.fullscreen);
    switch (e) {
    case EscapeEffect::CloseDialog:
        ui.quitDialogOpen = false;
        ui.saveDialogOpen = false;
        break;
    case EscapeEffect::CloseHelp:
        ui.helpOpen = false;
        break;
    case EscapeEffect::LeavePresent:
        setPresentMode(app.view, false);
        break;
    case EscapeEffect::LeaveFullscreen:
        ui.fullscreenRequested = true;
        break;
    case EscapeEffect::Nothing:
        if (keyboardBack) break; // that was its effect
        ui.messages.note = ui.inBrowser
                               ? "Esc closes windows and leaves present mode or full screen."
                               : "Esc closes windows and leaves present mode or fullscreen; "
                                 "Ctrl+Q quits.";
        break;
    }
    return e;
}

bool saveCurrentScene(App& app, const std::string& path) {
    Messages& m = app.ui.messages;
    if (path.empty()) {
        m.error = "Save: no file name given";
        return false;
    }
    const std::string where = absolutePath(path);
    std::string error;
    if (!app.sim.save(where, &error)) {
        m.error = "Save failed: " + (error.empty() ? where : error);
        return false;
    }
    m.error.clear();
    m.note = "Saved " + where;
    app.ui.savedFile = where;
    return true;
}

std::string saveDirectory(const App& app) {
    namespace fs = std::filesystem;
    std::string dir = workingDirectory();
    const std::string& scenePath = app.sim.scenePath;
    const std::string& scenesDir = app.shipped.scenesDir;
    if (!scenePath.empty()) {
        const fs::path sceneDir = fs::path(scenePath).parent_path();
        std::error_code ec;
        const bool shipped =
            !scenesDir.empty() && fs::equivalent(sceneDir, fs::path(scenesDir), ec) && !ec;
        if (!shipped && !sceneDir.empty()) dir = sceneDir.string();
    }
    return dir;
}

std::string suggestedSavePath(const App& app) {
    return suggestSavePath(app.sim.scene.name, saveDirectory(app), pathExists);
}

std::string browserDownloadPath(const App& app) {
    return std::string(kBrowserDownloads) + "/" + sceneFileStem(app.sim.scene.name) + ".json";
}

namespace {

// Writes `text` in saveDirectory(), named from the scene's name and `what` (never an existing
// file); the note says "Wrote `counted` to PATH" (the browser offers it as a download), or the
// error why not. Returns the path, or "".
std::string writeBeside(App& app, const std::string& what, const std::string& extension,
                        const std::string& text, const std::string& counted) {
    const std::string path =
        suggestSavePath(app.sim.scene.name + " " + what, saveDirectory(app), pathExists, extension);
    std::string error;
    if (!writeFileSafely(path, text, &error)) {
        app.ui.messages.error = "Export failed: " + error;
        return "";
    }
    app.ui.messages.error.clear();
    app.ui.messages.note = "Wrote " + counted + " to " + path;
    app.ui.savedFile = path;
    return path;
}

} // namespace

std::string saveEditLog(App& app) {
    const std::vector<JournalEntry>& journal = app.sim.editsSinceLoad();
    const std::string path = writeBeside(app, "edits", ".jsonl", logText(journal),
                                         std::to_string(journal.size()) + " edits");
    if (!path.empty() && app.sim.edits.journalFull())
        app.ui.messages.note +=
            " (the first " + std::to_string(kMaxJournal) + " only: the session has done more)";
    return path;
}

std::string exportCsv(App& app, const std::string& plot, const CsvTable& table) {
    std::ostringstream csv;
    writeCsv(csv, table);
    return writeBeside(app, plot, ".csv", csv.str(), std::to_string(table.rows.size()) + " rows");
}

bool openLesson(App& app, const std::string& path, std::size_t first) {
    const bool opened = openLesson(app.lesson, app.sim, app.view, app.ui.messages, path,
                                   app.shipped.scenesDir, first);
    if (opened) afterLessonAction(app);
    return opened;
}

void closeLesson(App& app) {
    closeLesson(app.lesson, app.sim, app.view);
}

bool enterStep(App& app, std::size_t index) {
    const bool entered = enterStep(app.lesson, app.sim, app.view, app.ui.messages, index);
    if (entered) afterLessonAction(app);
    return entered;
}

bool applyLessonAction(App& app, Action action) {
    LessonSession& s = app.lesson;
    Messages& m = app.ui.messages;
    switch (action) {
    case Action::Reset: // the step again from its setup, the lecturer's changes kept
        if (!s.active()) return false;
        replayStep(s, app.sim, app.view, m);
        break;
    case Action::ResetToFile: // the step as written
        if (!s.active()) return false;
        enterStep(s, app.sim, app.view, m, s.current);
        break;
    case Action::LessonNext:
        lessonNext(s, app.sim, app.view, m);
        break;
    case Action::LessonPrevious:
        lessonPrevious(s, app.sim, app.view, m);
        break;
    case Action::LessonFirst:
        if (s.active()) enterStep(s, app.sim, app.view, m, 0);
        break;
    case Action::LessonLast:
        if (s.active()) enterStep(s, app.sim, app.view, m, s.lesson->steps.size() - 1);
        break;
    case Action::LessonJump:
        lessonJump(s, app.sim, app.view, m);
        break;
    default:
        return false;
    }
    afterLessonAction(app);
    return true;
}

void lessonShowPausePoint(App& app) {
    lessonShowPausePoint(app.lesson, app.sim, app.view);
}
