#include "app_state.h"

#include "app_config.h"
#include "placement.h"

#include <algorithm>
#include <cmath>

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
    restartRun(app);
}

bool loadScene(App& app, const std::string& path) {
    const SceneResult result = loadSceneFile(path);
    if (!result.scene) {
        app.error = result.error.text();
        return false;
    }
    closeLesson(app);
    setScene(app, *result.scene, path);
    app.error.clear();
    app.note.clear();
    return true;
}

void resetScene(App& app) {
    restartRun(app);
}

void stepSimulation(App& app) {
    if (isReplaying(app)) app.telemetry.truncateAfter(app.world.time);
    app.history.beforeStep(app.world);
    if (app.show.sideBySide) {
        if (!app.methods.running) app.methods.start(app.world);
        app.methods.step(app.world.settings);
    } else {
        app.methods.stop();
    }
    app.previousBlocks = app.world.blocks;
    const double frameStart = app.world.time;
    app.lastLog.clear();
    app.stats = app.world.step(&app.lastLog);
    app.history.afterStep(app.world);
    addStep(app.totals, app.stats);
    app.trails.record(app.world);
    app.telemetry.record(app.world, app.selected, app.lastLog);
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
    lessonAfterFrame(app);
}

bool isReplaying(const App& app) {
    return !app.history.empty() && app.world.frame < app.history.lastFrame();
}

bool scrubTo(App& app, std::uint64_t frame) {
    World w;
    if (!app.history.stateAt(frame, w)) return false;
    app.run() = Run(std::move(w));
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

void cycleMethod(App& app) {
    const int count = static_cast<int>(Method::Count);
    const int next = (static_cast<int>(app.world.settings.method) + 1) % count;
    app.world.settings.method = static_cast<Method>(next);
}

Scene currentScene(const App& app) {
    Scene original = app.scene;
    original.blocks.clear();
    for (const BlockLabel& label : app.labels) {
        BlockDef def;
        def.name = label.name;
        def.color = label.color;
        original.blocks.push_back(def);
    }
    return sceneFromWorld(app.world, original);
}

bool saveCurrentScene(App& app, const std::string& path) {
    if (path.empty()) {
        app.error = "Save: no file name given";
        return false;
    }
    std::string error;
    if (!saveSceneFile(currentScene(app), path, &error)) {
        app.error = "Save failed: " + (error.empty() ? path : error);
        return false;
    }
    app.error.clear();
    app.note = "Saved " + path;
    app.savedFile = path;
    return true;
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
    return app.selected;
}

void deleteSelected(App& app) {
    const int i = app.selected;
    if (i < 0 || i >= static_cast<int>(app.world.blocks.size())) return;
    app.world.blocks.erase(app.world.blocks.begin() + i);
    if (i < static_cast<int>(app.labels.size())) app.labels.erase(app.labels.begin() + i);
    app.selected = -1;
    app.mouse = MouseTool{};
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
        return app.labels[static_cast<std::size_t>(index)].name;
    }
    return "#" + std::to_string(index);
}

double panelWidth(float uiScale, double displayWidth) {
    return std::min(350.0 * static_cast<double>(uiScale), displayWidth * 0.45);
}

ScreenRect sceneViewport(const App& app, double displayWidth, double displayHeight) {
    const double top = app.lesson.active() ? std::min(app.captionHeight, displayHeight * 0.5) : 0.0;
    const double height = std::max(1.0, displayHeight - top);
    if (!app.uiVisible) return {0.0, top, displayWidth, height};
    const double panel = panelWidth(app.uiScale, displayWidth);
    return {panel, top, std::max(1.0, displayWidth - panel), height};
}

void updateCamera(App& app, double displayWidth, double displayHeight) {
    app.camera.setViewport(sceneViewport(app, displayWidth, displayHeight));
    if (app.autoFit) {
        app.camera.fit(app.fitBounds ? *app.fitBounds : app.world.bounds,
                       36.0 * static_cast<double>(app.uiScale));
    }
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
