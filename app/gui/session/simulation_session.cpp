#include "simulation_session.h"

#include "placement.h"
#include "save_naming.h"
#include "settings_table.h"
#include "text_format.h"

#include <cmath>
#include <cstdio>

namespace {

std::vector<BlockLabel> labelsOf(const Scene& scene) {
    std::vector<BlockLabel> labels;
    labels.reserve(scene.blocks.size());
    for (const BlockDef& def : scene.blocks) labels.push_back({def.name, def.color});
    return labels;
}

} // namespace

Run::Run(World start) : world(std::move(start)) {
    stats.momentum = totalMomentum(world);
    stats.kineticEnergy = kineticEnergy(world);
    stats.potentialEnergy = potentialEnergy(world);
}

void SimulationSession::restartRun() {
    run = Run(makeWorld(scene));
    labels = labelsOf(scene);
    clock.reset();
    history.clear();
    telemetry.clear();
    pausedByCollision = false;
    telemetry.record(world(), selected, {});
    if (selected >= static_cast<int>(world().blocks.size())) selected = -1;
}

void SimulationSession::setScene(const Scene& newScene, const std::string& path) {
    scene = newScene;
    scenePath = path;
    selected = -1;
    paused = true;
    blocksEdited = false;
    script.clear(); // a lesson step sets its own after this
    playerKeys = {};
    restartRun();
}

void SimulationSession::reset() {
    const WorldSettings chosen = world().settings;
    restartRun();
    world().settings = chosen;
}

void SimulationSession::resetToFile() {
    restartRun();
}

void SimulationSession::noteEdit(bool blocks) {
    if (blocks) blocksEdited = true;
    if (history.empty()) return;
    const bool replaying = isReplaying();
    history.editedAt(world());
    telemetry.truncateAfter(world().time);
    if (replaying) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "Edited at t = %.2f s during the replay: a new future starts here (the "
                      "recorded one after it is dropped).",
                      world().time);
        notice = text;
    }
}

bool SimulationSession::unsavedEdits() const {
    return hasUnsavedEdits(blocksEdited, scene.settings, world().settings);
}

FrameOutcome SimulationSession::step(bool sideBySide) {
    World& w = world();
    if (isReplaying()) telemetry.truncateAfter(w.time);
    history.beforeStep(w);
    // The held thrust is added to the block's own force for this frame only (F = m·a: the same
    // force accelerates a heavy block slowly and a light one fast), then taken off again.
    const int pushed = thrustedBlock();
    const Vec2 thrust = thrustForce();
    if (sideBySide) {
        if (!run.methods.running) run.methods.start(w);
        run.methods.step(w.settings, pushed, thrust);
    } else {
        run.methods.stop();
    }
    // The player's keys (player.h): a jump now, a push for this frame like the thrust's.
    const PlayerKeys keys =
        script.empty() ? playerKeys : scriptedKeys(script, w.time, w.settings.dt);
    const bool playing = scene.player && keys.any();
    const Vec2 push = playing ? applyPlayerKeys(w, *scene.player, keys) : Vec2{};
    run.previousBlocks = w.blocks;
    const double frameStart = w.time;
    run.lastLog.clear();
    std::vector<std::pair<int, Vec2>> ownForces; // the blocks pushed and their own forces
    auto addForce = [&](int i, Vec2 f) {
        if (i < 0 || f == Vec2{}) return;
        Block& b = w.blocks[static_cast<std::size_t>(i)];
        ownForces.emplace_back(i, b.force);
        b.force = b.force + f;
    };
    addForce(pushed, thrust);
    addForce(playing ? scene.player->block : -1, push);
    run.stats = w.step(&run.lastLog);
    for (auto it = ownForces.rbegin(); it != ownForces.rend(); ++it)
        w.blocks[static_cast<std::size_t>(it->first)].force = it->second;
    history.afterStep(w);
    // The timeline rebuilds frames by stepping keyframes, which knows nothing of the keys held:
    // a thrust or player frame's result is kept as a keyframe of its own (replays stay bit for
    // bit).
    if (pushed >= 0 || playing) history.editedAt(w);
    addStep(run.totals, run.stats);
    run.trails.record(w, &run.lastLog);
    telemetry.record(w, selected, run.lastLog);
    announcer.note(run.lastLog);
    if (soundOn(sound, inLesson)) {
        for (const Knock& k : sound.scheduler.admit(run.lastLog, w)) sound.queue.push_back(k);
    }
    // The point of impact of the watched block's latest collision (kept until the next one).
    FrameOutcome out;
    const int watched = telemetry.watched;
    bool watchedHit = false;
    for (const CollisionRecord& r : run.lastLog) {
        if (r.rest) continue;
        out.collided = true;
        if (r.block == watched || r.other == watched) watchedHit = true;
    }
    if (watchedHit) {
        run.poi = computePoi(run.previousBlocks, w.bounds, w.settings, frameStart, watched);
    }
    if (out.collided && pauseOnCollision) {
        paused = true;
        pausedByCollision = true;
    }
    if (pauseAtSceneEnd && reachesSceneEnd(scene, frameStart, w.time, w.settings.dt)) {
        paused = true;
        out.reachedEnd = true;
        notice = "The scene has made its point at t = " + formatQuantity(*scene.duration, "s") +
                 ": P plays on, R replays.";
    }
    if (stopAtFrame && w.frame >= *stopAtFrame) {
        paused = true;
        stopAtFrame.reset();
        out.reachedStop = true;
    }
    if (stopWhen && stopWhen(w, run.stats, run.lastLog)) {
        paused = true;
        out.reachedStop = true;
    }
    return out;
}

int SimulationSession::advance(double realSeconds, bool sideBySide) {
    if (paused) {
        clock.reset();
        return 0;
    }
    const double dt = world().settings.dt;
    const int ticks = clock.advance(realSeconds, dt, simulationRate(timeScale, slowMotion, dt));
    int ran = 0;
    while (ran < ticks && !paused) {
        step(sideBySide);
        ++ran;
    }
    return ran;
}

bool reachesSceneEnd(const Scene& scene, double frameStart, double frameEnd, double dt) {
    if (!scene.duration) return false;
    // Half a frame of slack: T/dt frames of dt end within rounding of T, on either side.
    const double end = *scene.duration - 0.5 * dt;
    return frameStart < end && frameEnd >= end;
}

bool SimulationSession::isReplaying() const {
    return !history.empty() && world().frame < history.lastFrame();
}

bool SimulationSession::scrubTo(std::uint64_t frame) {
    World w;
    if (!history.stateAt(frame, w)) return false;
    run = Run(std::move(w));
    // The inspector lists the last collisions up to the frame shown, not the newest recorded.
    const std::vector<CollisionRecord> upTo = history.collisionsUpTo(frame, kRecentCollisions);
    telemetry.recent.assign(upTo.begin(), upTo.end());
    labels.resize(world().blocks.size());
    if (selected >= static_cast<int>(world().blocks.size())) selected = -1;
    return true;
}

int SimulationSession::thrustedBlock() const {
    const int i = selected;
    if (!thrust.on || thrust.direction == Vec2{} || i < 0 ||
        i >= static_cast<int>(world().blocks.size()) ||
        !world().blocks[static_cast<std::size_t>(i)].isDynamic()) {
        return -1;
    }
    return i;
}

Vec2 SimulationSession::thrustForce() const {
    return thrustedBlock() < 0 ? Vec2{} : thrust.direction * thrust.force;
}

Vec2 SimulationSession::pushForce() const {
    if (thrustedBlock() >= 0) return thrustForce();
    if (!scene.player) return {};
    const World& w = world();
    const PlayerKeys keys =
        script.empty() ? playerKeys : scriptedKeys(script, w.time, w.settings.dt);
    return playerPush(w, *scene.player, keys);
}

int SimulationSession::pushedBlock() const {
    if (thrustedBlock() >= 0) return thrustedBlock();
    return pushForce() == Vec2{} ? -1 : scene.player->block;
}

Vec2 SimulationSession::appliedForce(int index) const {
    if (index < 0 || index >= static_cast<int>(world().blocks.size())) return {};
    const Vec2 own = world().blocks[static_cast<std::size_t>(index)].force;
    return index == pushedBlock() ? own + pushForce() : own;
}

bool SimulationSession::usesPhysicsSection() const {
    if (thrust.on) return true;
    const WorldSettings defaults = defaultWorldSettings();
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (row.panel.section == settings_table::Section::Physics &&
            !settings_table::same(row, scene.settings, defaults))
            return true;
    }
    for (const BlockDef& b : scene.blocks) {
        if (b.force != Vec2{} || b.friction >= 0.0) return true;
    }
    return false;
}

void SimulationSession::cycleMethod() {
    const int count = static_cast<int>(Method::Count);
    const int next = (static_cast<int>(world().settings.method) + 1) % count;
    world().settings.method = static_cast<Method>(next);
    noteEdit(false);
}

void SimulationSession::setBlockKind(int index, BodyKind kind) {
    if (index < 0 || index >= static_cast<int>(world().blocks.size())) return;
    Block& b = world().blocks[static_cast<std::size_t>(index)];
    if (b.kind == kind) return;
    b.kind = kind;
    if (kind == BodyKind::Dynamic) {
        if (!(std::isfinite(b.mass) && b.mass > 0.0)) b.mass = 1.0;
    } else {
        b.mass = kInfiniteMass;
        if (kind == BodyKind::Static) b.velocity = Vec2{};
    }
    noteEdit(true);
}

bool SimulationSession::setBlockSize(int index, Vec2 size) {
    if (index < 0 || index >= static_cast<int>(world().blocks.size())) return false;
    if (!(size.x > 0.0 && size.y > 0.0) || !std::isfinite(size.x) || !std::isfinite(size.y)) {
        return false;
    }
    Block& b = world().blocks[static_cast<std::size_t>(index)];
    const Bounds& bounds = world().bounds;
    const Vec2 h = size * 0.5;
    if (b.position.x - h.x < bounds.min.x || b.position.x + h.x > bounds.max.x ||
        b.position.y - h.y < bounds.min.y || b.position.y + h.y > bounds.max.y) {
        return false;
    }
    if (overlapsAnyBlock(world(), index, b.position, size)) return false;
    b.size = size;
    noteEdit(true);
    return true;
}

int SimulationSession::addBlockAt(Vec2 at) {
    const Vec2 size{1.0, 1.0};
    const auto spot = placeWithoutOverlap(world(), -1, at, size);
    if (!spot) {
        notice = "No room for a new block there";
        return -1;
    }
    Block block;
    block.position = *spot;
    block.size = size;
    block.mass = 1.0;
    block.kind = BodyKind::Dynamic;
    world().blocks.push_back(block);
    labels.push_back({"new " + std::to_string(world().blocks.size()), ""});
    selected = static_cast<int>(world().blocks.size()) - 1;
    noteEdit(true);
    return selected;
}

void SimulationSession::deleteSelected() {
    const int i = selected;
    if (i < 0 || i >= static_cast<int>(world().blocks.size())) return;
    world().blocks.erase(world().blocks.begin() + i);
    if (i < static_cast<int>(labels.size())) labels.erase(labels.begin() + i);
    selected = -1;
    noteEdit(true);
}

Scene SimulationSession::currentScene() const {
    return sceneOf(world());
}

Scene SimulationSession::sceneOf(const World& w) const {
    Scene original = scene;
    original.blocks.clear();
    for (std::size_t i = 0; i < labels.size(); ++i) {
        BlockDef def;
        def.name =
            i < w.blocks.size() ? nameWithMass(labels[i].name, w.blocks[i].mass) : labels[i].name;
        def.color = labels[i].color;
        original.blocks.push_back(def);
    }
    original.description = savedDescription(scene.description, scene.settings, w.settings);
    return sceneFromWorld(w, original);
}

bool SimulationSession::save(const std::string& path, std::string* error) {
    const Scene saved = currentScene();
    if (!saveSceneFile(saved, path, error)) return false;
    // The saved file is now the current scene's: the settings remember it, reset to file and R
    // go back to it, and there is nothing unsaved.
    scene = saved;
    scenePath = path;
    labels = labelsOf(saved);
    blocksEdited = false;
    return true;
}

std::string SimulationSession::blockDisplayName(int index) const {
    if (index >= 0 && index < static_cast<int>(labels.size()) &&
        !labels[static_cast<std::size_t>(index)].name.empty()) {
        const std::string& name = labels[static_cast<std::size_t>(index)].name;
        // A name that states a mass ("m1 = 1 kg") states the current one.
        if (index < static_cast<int>(world().blocks.size())) {
            return nameWithMass(name, world().blocks[static_cast<std::size_t>(index)].mass);
        }
        return name;
    }
    return "#" + std::to_string(index);
}

Color SimulationSession::blockDisplayColor(int index) const {
    if (index < 0 || index >= static_cast<int>(world().blocks.size())) return {};
    const std::size_t i = static_cast<std::size_t>(index);
    const std::string color = i < labels.size() ? labels[i].color : std::string();
    Color c;
    if (parseHexColor(color, c)) return c;
    switch (world().blocks[i].kind) {
    case BodyKind::Static:
        return staticBlockColor();
    case BodyKind::Kinematic:
        return kinematicBlockColor();
    case BodyKind::Dynamic:
        break;
    }
    return blockColor(index, "");
}
