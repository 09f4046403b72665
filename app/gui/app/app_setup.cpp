#include "app_setup.h"

#include "printable.h"

#ifndef SANDBOX_SCENES_DIR
#define SANDBOX_SCENES_DIR ""
#endif

std::string builtInScenesDirectory() {
    return SANDBOX_SCENES_DIR;
}

namespace {

// The lesson or scene to start with (see setupApp).
bool openFirst(App& app, const Options& options, const std::string& lastScene, std::string* error) {
    // A lesson: --lesson NAME, or a lesson file given as the scene.
    std::string lesson;
    if (!options.lesson.empty()) {
        lesson =
            resolveScenePath(options.lesson, app.shipped.lessonsDir); // NAME, NAME.json or a path
    } else if (!options.scene.empty()) {
        const std::string path = resolveScenePath(options.scene, app.shipped.scenesDir);
        if (isLessonFile(path)) lesson = path;
    }
    if (!lesson.empty()) {
        const std::size_t first = options.step > 0 ? static_cast<std::size_t>(options.step - 1) : 0;
        if (!openLesson(app, lesson, first)) {
            if (error) *error = app.ui.messages.error;
            return false;
        }
        if (!options.pollAddress.empty() &&
            !startPoll(app.poll, app.lesson, app.sim, options.pollAddress)) {
            if (error) *error = "--poll: " + app.poll.error;
            return false;
        }
        return true;
    }
    if (!options.pollAddress.empty()) {
        if (error) *error = "--poll needs a lesson (--lesson NAME or a lesson file)";
        return false;
    }
    if (options.step > 0) {
        if (error) *error = "--step needs a lesson (--lesson NAME or a lesson file)";
        return false;
    }
    if (options.atSetup) {
        if (error) *error = "--at needs a lesson (--lesson NAME or a lesson file)";
        return false;
    }

    if (!options.scene.empty()) {
        const std::string path = resolveScenePath(options.scene, app.shipped.scenesDir);
        if (!loadScene(app, path)) {
            if (error) *error = app.ui.messages.error;
            return false;
        }
        return true;
    }
    // The last scene (a saved setting) may be a file that no longer loads: the default opens and
    // the reason stays in the panel's message (the window also prints it as a settings warning).
    std::string lastSceneError;
    if (!lastScene.empty()) {
        if (loadScene(app, lastScene)) return true;
        lastSceneError = "the last scene does not open, the default does: " + app.ui.messages.error;
    }
    const std::string fallback = resolveScenePath(kDefaultSceneFile, app.shipped.scenesDir);
    if (loadScene(app, fallback)) {
        app.ui.messages.error = lastSceneError;
        return true;
    }
    // Nothing loads: an empty world, with the reason on screen.
    Scene empty;
    empty.name = "(no scene)";
    const std::string why = app.ui.messages.error;
    setScene(app, empty, "");
    app.ui.messages.error = why.empty() ? "No scene found" : why;
    return true;
}

// --set's edits at the start, then --edits's log (its lines at frame 0 at once).
bool startEdits(App& app, const Options& options, std::string* error) {
    for (const std::string& text : options.sets) {
        EditError refused;
        const std::optional<Edit> edit = parseSet(text, refused);
        if (edit) refused = app.sim.apply(*edit);
        if (refused.empty()) continue;
        if (error) *error = printable("--set " + text + ": " + refused.text());
        return false;
    }
    if (options.edits.empty()) return true;
    EditLogResult log = readEditLog(options.edits);
    if (!log.log) {
        if (error) *error = log.error.text();
        return false;
    }
    app.sim.editLog = LogPlayer(std::move(*log.log));
    app.sim.playEditLog();
    if (app.sim.editLogError.empty()) return true;
    if (error) *error = app.sim.editLogError;
    return false;
}

} // namespace

bool setupApp(App& app, const Options& options, const std::string& lastScene, std::string* error) {
    app.shipped.scenesDir = findScenesDirectory(executableDirectory(), builtInScenesDirectory());
    app.shipped.scenes = listScenes(app.shipped.scenesDir);
    app.shipped.lessonsDir =
        findDataDirectory(executableDirectory(), builtInLessonsDirectory(), "lessons");
    app.shipped.lessons = listScenes(app.shipped.lessonsDir);
    app.log.verbose = options.verbose;
    app.sim.verbose = options.verbose;
    if (options.showGiven) applyShowSet(app.view, options.show);
    if (!openFirst(app, options, lastScene, error)) return false;
    if (!startEdits(app, options, error)) return false;
    // --compare: the trace opened on that scene, at its first difference.
    app.studentTrace.units = options.traceUnits;
    if (!options.compareTrace.empty() && !openTrace(app, options.compareTrace)) {
        if (error) *error = app.ui.messages.error;
        return false;
    }
    // --frame: the run has just started, so the camera follows from its start (the anchor the
    // run set stays; setViewFrame would anchor at the first frame drawn, after --frames N).
    if (options.frame) app.view.frame = *options.frame;
    return true;
}
