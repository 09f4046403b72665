#include "app_state.h"

#include "app_config.h"
#include "classroom.h"
#include "overlays.h"
#include "placement.h"
#include "save_naming.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

std::vector<BlockLabel> labelsOf(const Scene& scene) {
    std::vector<BlockLabel> labels;
    labels.reserve(scene.blocks.size());
    for (const BlockDef& def : scene.blocks) labels.push_back({def.name, def.color});
    return labels;
}

void restartRun(App& app) {
    app.run() = Run(makeWorld(app.scene));
    app.labels = labelsOf(app.scene);
    app.clock.reset();
    app.history.clear();
    app.telemetry.clear();
    app.pausedByCollision = false;
    app.telemetry.record(app.world, app.selected, {});
    app.mouse = MouseTool{};
    anchorFrameCamera(app.frameCamera, app.world); // the view follows from the run's start
    if (app.selected >= static_cast<int>(app.world.blocks.size())) app.selected = -1;
}

} // namespace

Run::Run(World start) : world(std::move(start)) {
    stats.momentum = totalMomentum(world);
    stats.kineticEnergy = kineticEnergy(world);
    stats.potentialEnergy = potentialEnergy(world);
}

void setScene(App& app, const Scene& scene, const std::string& path) {
    app.scene = scene;
    if (!app.overlaysChosen) app.show.vectors = scene.blocks.size() <= kVectorsByDefaultUpTo;
    app.scenePath = path;
    app.selected = -1;
    app.autoFit = true;
    app.paused = true;
    app.blocksEdited = false;
    app.ui.typedWarning.clear();
    closeTrace(app); // compared with another scene
    restartRun(app);
}

namespace {

std::string workingDirectory() {
    std::error_code ec;
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    return ec ? std::string() : cwd.string();
}

} // namespace

bool loadScene(App& app, const std::string& path) {
    const SceneResult result = loadSceneFile(path);
    if (!result.scene) {
        app.error = result.error.text();
        return false;
    }
    closeLesson(app);
    // The absolute path: the settings remember it, and it must work from any directory.
    const std::string cwd = workingDirectory();
    setScene(app, *result.scene, cwd.empty() ? path : absoluteScenePath(path, cwd));
    app.error.clear();
    app.note.clear();
    return true;
}

void resetScene(App& app) {
    const WorldSettings chosen = app.world.settings;
    restartRun(app);
    app.world.settings = chosen;
}

bool openTrace(App& app, const std::string& path) {
    if (const auto error = openStudentTrace(app.studentTrace, path, app.scene, app.world.settings,
                                            app.studentTrace.units)) {
        app.error = *error;
        return false;
    }
    app.error.clear();
    app.tracePath = path;
    // The reference runs from the scene's start, without the Tips' mistakes.
    app.world.settings = app.studentTrace.comparison->reference;
    resetScene(app);
    app.show.ghost = app.show.timeline = app.show.inspector = true;
    goToFirstDifference(app);
    app.note = "Your trace: " + studentTraceSummary(app.studentTrace) + ".";
    return true;
}

bool compareTraceAgain(App& app) {
    if (!app.studentTrace.open()) return false;
    return openTrace(app, app.studentTrace.path);
}

bool goToFirstDifference(App& app) {
    const std::int64_t frame = app.studentTrace.firstDifference();
    if (frame < 0) return false;
    const auto target = static_cast<std::uint64_t>(frame);
    app.paused = true;
    if (!app.history.empty() && target >= app.history.firstFrame() &&
        target <= app.history.lastFrame())
        return scrubTo(app, target);
    if (app.world.frame > target) resetScene(app);
    while (app.world.frame < target) stepSimulation(app);
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
    restartRun(app);
}

void noteEdit(App& app, bool blocks) {
    if (blocks) app.blocksEdited = true;
    if (app.history.empty()) return;
    const bool replaying = isReplaying(app);
    app.history.editedAt(app.world);
    app.telemetry.truncateAfter(app.world.time);
    if (replaying) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "Edited at t = %.2f s during the replay: a new future starts here (the "
                      "recorded one after it is dropped).",
                      app.world.time);
        app.note = text;
    }
}

bool unsavedEdits(const App& app) {
    return hasUnsavedEdits(app.blocksEdited, app.scene.settings, app.world.settings);
}

void requestQuit(App& app) {
    if (app.quitDialogOpen || !unsavedEdits(app)) {
        app.quitRequested = true;
        return;
    }
    app.quitDialogOpen = true;
}

void setPresentMode(App& app, bool on) {
    app.presentMode = on;
    app.autoFit = true; // the scene's rectangle changes: fit the world into it again
}

EscapeEffect pressEscape(App& app) {
    const EscapeEffect e = escapeEffect(app.quitDialogOpen || app.saveDialogOpen, app.helpOpen,
                                        app.presentMode, app.fullscreen);
    switch (e) {
    case EscapeEffect::CloseDialog:
        app.quitDialogOpen = false;
        app.saveDialogOpen = false;
        break;
    case EscapeEffect::CloseHelp:
        app.helpOpen = false;
        break;
    case EscapeEffect::LeavePresent:
        setPresentMode(app, false);
        break;
    case EscapeEffect::LeaveFullscreen:
        app.fullscreenRequested = true;
        break;
    case EscapeEffect::Nothing:
        app.note = "Esc closes windows and leaves present mode or fullscreen; Ctrl+Q quits.";
        break;
    }
    return e;
}

void stepSimulation(App& app) {
    if (isReplaying(app)) app.telemetry.truncateAfter(app.world.time);
    app.history.beforeStep(app.world);
    // The held thrust is added to the block's own force for this frame only (F = m·a: the same
    // force accelerates a heavy block slowly and a light one fast), then taken off again.
    const int pushed = thrustedBlock(app);
    const Vec2 thrust = thrustForce(app);
    if (app.show.sideBySide) {
        if (!app.methods.running) app.methods.start(app.world);
        app.methods.step(app.world.settings, pushed, thrust);
    } else {
        app.methods.stop();
    }
    app.previousBlocks = app.world.blocks;
    const double frameStart = app.world.time;
    app.lastLog.clear();
    Vec2 ownForce;
    if (pushed >= 0) {
        Block& b = app.world.blocks[static_cast<std::size_t>(pushed)];
        ownForce = b.force;
        b.force = ownForce + thrust;
    }
    app.stats = app.world.step(&app.lastLog);
    if (pushed >= 0) app.world.blocks[static_cast<std::size_t>(pushed)].force = ownForce;
    app.history.afterStep(app.world);
    // The timeline rebuilds frames by stepping keyframes, which knows nothing of the keys held:
    // a thrust frame's result is kept as a keyframe of its own (replays stay bit for bit).
    if (pushed >= 0) app.history.editedAt(app.world);
    addStep(app.totals, app.stats);
    app.trails.record(app.world);
    app.telemetry.record(app.world, app.selected, app.lastLog);
    app.announcer.note(app.lastLog);
    if (soundOn(app.sound, app.lesson.active())) {
        for (const Knock& k : app.sound.scheduler.admit(app.lastLog, app.world))
            app.sound.queue.push_back(k);
    }
    // The point of impact of the watched block's latest collision (kept until the next one).
    const int watched = app.telemetry.watched;
    bool collided = false, watchedHit = false;
    for (const CollisionRecord& r : app.lastLog) {
        if (r.rest) continue;
        collided = true;
        if (r.block == watched || r.other == watched) watchedHit = true;
    }
    if (watchedHit) {
        app.poi = computePoi(app.previousBlocks, app.world.bounds, app.world.settings, frameStart,
                             watched);
    }
    if (collided && app.pauseOnCollision) {
        app.paused = true;
        app.pausedByCollision = true;
    }
    if (reachesSceneEnd(app.scene, frameStart, app.world.time, app.world.settings.dt) &&
        !app.lesson.active()) {
        app.paused = true;
        app.note =
            "The scene has made its point at t = " + formatQuantity(*app.scene.duration, "s") +
            ": P plays on, R replays.";
    }
    lessonAfterFrame(app);
}

bool reachesSceneEnd(const Scene& scene, double frameStart, double frameEnd, double dt) {
    if (!scene.duration) return false;
    // Half a frame of slack: T/dt frames of dt end within rounding of T, on either side.
    const double end = *scene.duration - 0.5 * dt;
    return frameStart < end && frameEnd >= end;
}

bool isReplaying(const App& app) {
    return !app.history.empty() && app.world.frame < app.history.lastFrame();
}

bool scrubTo(App& app, std::uint64_t frame) {
    World w;
    if (!app.history.stateAt(frame, w)) return false;
    app.run() = Run(std::move(w));
    // The inspector lists the last collisions up to the frame shown, not the newest recorded.
    const std::vector<CollisionRecord> upTo = app.history.collisionsUpTo(frame, kRecentCollisions);
    app.telemetry.recent.assign(upTo.begin(), upTo.end());
    app.ui.inspectorPicked = 0;
    app.labels.resize(app.world.blocks.size());
    app.mouse = MouseTool{};
    if (app.selected >= static_cast<int>(app.world.blocks.size())) app.selected = -1;
    return true;
}

int advanceSimulation(App& app, double realSeconds) {
    if (app.paused || app.mouse.holdsSimulation()) {
        app.clock.reset();
        return 0;
    }
    const double dt = app.world.settings.dt;
    const int ticks =
        app.clock.advance(realSeconds, dt, simulationRate(app.timeScale, app.slowMotion, dt));
    int ran = 0;
    while (ran < ticks && !app.paused) {
        stepSimulation(app);
        ++ran;
    }
    return ran;
}

int thrustedBlock(const App& app) {
    const int i = app.selected;
    if (!app.thrust.on || app.thrust.direction == Vec2{} || i < 0 ||
        i >= static_cast<int>(app.world.blocks.size()) ||
        !app.world.blocks[static_cast<std::size_t>(i)].isDynamic()) {
        return -1;
    }
    return i;
}

Vec2 thrustForce(const App& app) {
    return thrustedBlock(app) < 0 ? Vec2{} : app.thrust.direction * app.thrust.force;
}

Vec2 appliedForce(const App& app, int index) {
    if (index < 0 || index >= static_cast<int>(app.world.blocks.size())) return {};
    const Vec2 own = app.world.blocks[static_cast<std::size_t>(index)].force;
    return index == thrustedBlock(app) ? own + thrustForce(app) : own;
}

bool usesPhysicsSection(const App& app) {
    const WorldSettings& s = app.scene.settings;
    const WorldSettings d = defaultWorldSettings();
    if (app.thrust.on || s.resolve != d.resolve || s.integrator != d.integrator ||
        s.mistakes != d.mistakes || s.drag != d.drag) {
        return true;
    }
    for (const BlockDef& b : app.scene.blocks) {
        if (b.force != Vec2{}) return true;
    }
    return false;
}

void cycleMethod(App& app) {
    const int count = static_cast<int>(Method::Count);
    const int next = (static_cast<int>(app.world.settings.method) + 1) % count;
    app.world.settings.method = static_cast<Method>(next);
    noteEdit(app, false);
}

Scene currentScene(const App& app) {
    Scene original = app.scene;
    original.blocks.clear();
    for (std::size_t i = 0; i < app.labels.size(); ++i) {
        BlockDef def;
        def.name = i < app.world.blocks.size()
                       ? nameWithMass(app.labels[i].name, app.world.blocks[i].mass)
                       : app.labels[i].name;
        def.color = app.labels[i].color;
        original.blocks.push_back(def);
    }
    original.description =
        savedDescription(app.scene.description, app.scene.settings, app.world.settings);
    return sceneFromWorld(app.world, original);
}

bool saveCurrentScene(App& app, const std::string& path) {
    if (path.empty()) {
        app.error = "Save: no file name given";
        return false;
    }
    const std::string cwd = workingDirectory();
    const std::string where = cwd.empty() ? path : absoluteScenePath(path, cwd);
    const Scene scene = currentScene(app);
    std::string error;
    if (!saveSceneFile(scene, where, &error)) {
        app.error = "Save failed: " + (error.empty() ? where : error);
        return false;
    }
    // The saved file is now the current scene's: the settings remember it, reset to file and R
    // go back to it, and there is nothing unsaved.
    app.scene = scene;
    app.scenePath = where;
    app.labels.clear();
    for (const BlockDef& def : scene.blocks) app.labels.push_back({def.name, def.color});
    app.blocksEdited = false;
    app.error.clear();
    app.note = "Saved " + where;
    app.savedFile = where;
    return true;
}

std::string saveDirectory(const App& app) {
    namespace fs = std::filesystem;
    std::string dir = workingDirectory();
    if (!app.scenePath.empty()) {
        const fs::path sceneDir = fs::path(app.scenePath).parent_path();
        std::error_code ec;
        const bool shipped =
            !app.scenesDir.empty() && fs::equivalent(sceneDir, fs::path(app.scenesDir), ec) && !ec;
        if (!shipped && !sceneDir.empty()) dir = sceneDir.string();
    }
    return dir;
}

bool pathExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

std::string suggestedSavePath(const App& app) {
    return suggestSavePath(app.scene.name, saveDirectory(app), pathExists);
}

bool isFloating(const App& app, const std::string& title) {
    return std::find(app.floatingWindows.begin(), app.floatingWindows.end(), title) !=
           app.floatingWindows.end();
}

void setFloating(App& app, const std::string& title, bool floating) {
    auto& f = app.floatingWindows;
    f.erase(std::remove(f.begin(), f.end(), title), f.end());
    if (floating) f.push_back(title);
}

int addBlockAt(App& app, Vec2 at) {
    const Vec2 size{1.0, 1.0};
    const auto spot = placeWithoutOverlap(app.world, -1, at, size);
    if (!spot) {
        app.note = "No room for a new block there";
        return -1;
    }
    Block block;
    block.position = *spot;
    block.size = size;
    block.mass = 1.0;
    block.kind = BodyKind::Dynamic;
    app.world.blocks.push_back(block);
    app.labels.push_back({"", ""});
    app.labels.back().name = "new " + std::to_string(app.world.blocks.size());
    app.selected = static_cast<int>(app.world.blocks.size()) - 1;
    noteEdit(app, true);
    return app.selected;
}

void deleteSelected(App& app) {
    const int i = app.selected;
    if (i < 0 || i >= static_cast<int>(app.world.blocks.size())) return;
    app.world.blocks.erase(app.world.blocks.begin() + i);
    if (i < static_cast<int>(app.labels.size())) app.labels.erase(app.labels.begin() + i);
    app.selected = -1;
    app.mouse = MouseTool{};
    noteEdit(app, true);
}

void applyShowSet(App& app, const ShowSet& show) {
    app.overlaysChosen = true;
    app.uiVisible = !show.none;
    app.show = show.overlays;
}

void setUiScale(App& app, float scale) {
    if (!(scale == scale)) return;
    app.uiScale = std::clamp(scale, kMinUiScale, kMaxUiScale);
}

std::string blockDisplayName(const App& app, int index) {
    if (index >= 0 && index < static_cast<int>(app.labels.size()) &&
        !app.labels[static_cast<std::size_t>(index)].name.empty()) {
        const std::string& name = app.labels[static_cast<std::size_t>(index)].name;
        // A name that states a mass ("m1 = 1 kg") states the current one.
        if (index < static_cast<int>(app.world.blocks.size())) {
            return nameWithMass(name, app.world.blocks[static_cast<std::size_t>(index)].mass);
        }
        return name;
    }
    return "#" + std::to_string(index);
}

double panelWidth(float uiScale, double displayWidth) {
    return std::min(350.0 * static_cast<double>(uiScale), displayWidth * 0.45);
}

Layout computeAppLayout(const App& app, double displayWidth, double displayHeight) {
    LayoutInput in;
    in.displayWidth = displayWidth;
    in.displayHeight = displayHeight;
    in.uiScale = app.uiScale;
    // A lesson's caption bar over the top of the scene (and the column), presenting too.
    if (app.lesson.active()) in.topInset = std::min(app.captionHeight, displayHeight * 0.5);
    if (app.presentMode) return computeLayout(in); // the scene alone (under a lesson's caption)
    in.panelWidth = app.uiVisible ? panelWidth(app.uiScale, displayWidth) : 0.0;
    for (const OverlayInfo& row : kOverlays) {
        if (!row.title || !(app.show.*row.flag) || isFloating(app, row.title)) continue;
        in.windows.push_back({row.title, row.place.side, row.place.minExtent, row.place.weight,
                              row.place.crossExtent});
    }
    return computeLayout(in);
}

ScreenRect sceneViewport(const App& app, double displayWidth, double displayHeight) {
    return computeAppLayout(app, displayWidth, displayHeight).scene;
}

void updateCamera(App& app, double displayWidth, double displayHeight) {
    app.layout = computeAppLayout(app, displayWidth, displayHeight);
    app.camera.setViewport(app.layout.scene);
    if (app.autoFit) {
        app.camera.fit(app.fitBounds ? *app.fitBounds : app.world.bounds,
                       kFitMarginPx * static_cast<double>(app.uiScale));
    }
    app.camera.setCentre(app.camera.centre() +
                         followShift(app.frameCamera, app.world, app.frame, app.autoFit));
}

void setViewFrame(App& app, ViewFrame frame) {
    app.frame = frame;
    app.frameCamera.anchored = false;
}

void setBlockKind(App& app, int index, BodyKind kind) {
    if (index < 0 || index >= static_cast<int>(app.world.blocks.size())) return;
    Block& b = app.world.blocks[static_cast<std::size_t>(index)];
    if (b.kind == kind) return;
    b.kind = kind;
    if (kind == BodyKind::Dynamic) {
        if (!(std::isfinite(b.mass) && b.mass > 0.0)) b.mass = 1.0;
    } else {
        b.mass = kInfiniteMass;
        if (kind == BodyKind::Static) b.velocity = Vec2{};
    }
    noteEdit(app, true);
}

bool setBlockSize(App& app, int index, Vec2 size) {
    if (index < 0 || index >= static_cast<int>(app.world.blocks.size())) return false;
    if (!(size.x > 0.0 && size.y > 0.0) || !std::isfinite(size.x) || !std::isfinite(size.y)) {
        return false;
    }
    Block& b = app.world.blocks[static_cast<std::size_t>(index)];
    const Bounds& bounds = app.world.bounds;
    const Vec2 h = size * 0.5;
    if (b.position.x - h.x < bounds.min.x || b.position.x + h.x > bounds.max.x ||
        b.position.y - h.y < bounds.min.y || b.position.y + h.y > bounds.max.y) {
        return false;
    }
    if (overlapsAnyBlock(app.world, index, b.position, size)) return false;
    b.size = size;
    noteEdit(app, true);
    return true;
}

void noteFrameShown(App& app, double realSeconds) {
    if (!(realSeconds > 0.0)) return;
    const double ms = realSeconds * 1000.0;
    app.frameMsSmoothed =
        app.framesShown == 0 ? ms : app.frameMsSmoothed + (ms - app.frameMsSmoothed) / 30.0;
    ++app.framesShown;
    app.secondsShown += realSeconds;
}

Color blockDisplayColor(const App& app, int index) {
    if (index < 0 || index >= static_cast<int>(app.world.blocks.size())) return {};
    const std::size_t i = static_cast<std::size_t>(index);
    const std::string color = i < app.labels.size() ? app.labels[i].color : std::string();
    Color c;
    if (parseHexColor(color, c)) return c;
    switch (app.world.blocks[i].kind) {
    case BodyKind::Static:
        return staticBlockColor();
    case BodyKind::Kinematic:
        return kinematicBlockColor();
    case BodyKind::Dynamic:
        break;
    }
    return blockColor(index, "");
}
