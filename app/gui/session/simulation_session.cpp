#include "simulation_session.h"

#include "edit_words.h"
#include "input_limits.h"
#include "panel_rows.h"
#include "placement.h"
#include "printable.h"
#include "save_naming.h"
#include "scene_json.h"
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

void SimulationSession::setScene(const Scene& newScene, const std::string& path,
                                 const std::vector<Edit>& setup) {
    scene = newScene;
    scenePath = path;
    ++changes;
    lastChange.clear();
    selected = -1;
    paused = true;
    blocksEdited = false;
    script.clear(); // a lesson step sets its own after this
    playerKeys = {};
    editLog = LogPlayer{}; // a log is of the scene it was given with
    editLogError.clear();
    restartRun();
    edits.clear();
    for (const Edit& edit : setup) printChange("setup: " + editLogLine(edit, -1, world(), labels));
}

void SimulationSession::reset() {
    const WorldSettings chosen = world().settings;
    restartRun();
    // A new run: the undo history and the journal start again, with the settings kept as edits
    // at frame 0 (so the journal replays this run from the scene, and undo can take them back).
    edits.clear();
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (row.inScene && !settings_table::same(row, world().settings, chosen))
            apply(Edit::setWorld(row.key, settingJson(row, chosen)));
    }
    editLog.restart();
    playEditLog();
}

void SimulationSession::resetToFile() {
    restartRun();
    edits.clear();
    editLog.restart();
    playEditLog();
}

EditError SimulationSession::apply(const Edit& edit, bool continues) {
    const ApplyResult r = edits.apply({world(), labels}, edit, world().frame, continues);
    if (!r.applied) return r.error;
    afterEdit(*r.applied, false);
    const bool named = !edits.journalFull() && !edits.journal().empty();
    printChange(
        editLogLine(named ? edits.journal().back().edit : edit, r.applied->index, world(), labels));
    return {};
}

bool SimulationSession::undo() {
    EditError error;
    return undoOrRedo(true, error);
}

bool SimulationSession::redo() {
    EditError error;
    return undoOrRedo(false, error);
}

bool SimulationSession::undoOrRedo(bool back, EditError& error) {
    const EditTarget target{world(), labels};
    const UndoResult r =
        back ? edits.undo(target, world().frame) : edits.redo(target, world().frame);
    const char* what = back ? "undo" : "redo";
    if (!r.edit) {
        notice = r.error.empty()
                     ? std::string(back ? "Nothing to undo" : "Nothing to redo")
                     : std::string(back ? "Cannot undo: " : "Cannot redo: ") + r.error.text();
        printChange(std::string(what) + ": " + (r.error.empty() ? "nothing" : r.error.text()));
        error = r.error;
        return false;
    }
    afterEdit(*r.edit, back);
    notice = std::string(what) + ": " + editChangeText(*r.edit, back, labels);
    printChange(notice);
    return true;
}

void SimulationSession::playEditLog() {
    while (const LogLine* line = editLog.next(world().frame)) {
        const JournalEntry& e = line->entry;
        EditError error;
        if (e.what == JournalEntry::What::Edit)
            error = apply(e.edit, e.continues);
        else
            undoOrRedo(e.what == JournalEntry::What::Undo, error);
        if (error.empty()) continue;
        editLogError = logLineError(*line, error).text();
        notice = editLogError;
        editLog = LogPlayer{}; // the rest would apply to a world it was not written for
        return;
    }
}

void SimulationSession::restartShowingChanges(const std::function<void()>& restart) {
    const WorldSettings before = world().settings;
    restart();
    for (const settings_table::WorldKey* row : panelOrder())
        if (!settings_table::same(*row, before, world().settings))
            printChange(row->key + std::string(": ") +
                        settings_table::logValue(*row, world().settings));
}

void SimulationSession::printChange(const std::string& line) const {
    if (!verbose) return;
    std::printf("%s\n", printable(line, kPrintablePath).c_str()); // names come from files
    std::fflush(stdout);
}

void SimulationSession::afterEdit(const AppliedEdit& a, bool undone) {
    ++changes;
    lastChange = editNowText(a, undone, labels);
    const bool blocks = a.edit.kind != Edit::Kind::SetWorld;
    // The selection follows blocks added and removed before it.
    if (a.edit.kind == Edit::Kind::Add || a.edit.kind == Edit::Kind::Remove) {
        const bool inserted = (a.edit.kind == Edit::Kind::Add) != undone;
        if (inserted && selected >= a.index)
            ++selected;
        else if (!inserted && selected == a.index)
            selected = -1;
        else if (!inserted && selected > a.index)
            --selected;
    }
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
    w.settings.measureTime = stepTimeShown || sideBySide; // not a physics setting: no edit
    // The player's keys (player.h): a jump now, a push for this frame like the thrust's.
    const PlayerKeys keys =
        script.empty() ? playerKeys : scriptedKeys(script, w.time, w.settings.dt);
    const bool playing = scene.player && keys.any();
    // The side-by-side run of the live method, while it is the live world bit for bit and the
    // live world feels no force of its own this frame, takes the live step (not computed twice).
    Method followed = Method::Count;
    if (sideBySide) {
        if (!run.methods.running) run.methods.start(w);
        if (pushed < 0 && !playing) followed = run.methods.following(w);
        run.methods.step(w.settings, pushed, thrust, followed);
    } else {
        run.methods.stop();
    }
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
    run.methods.follow(followed, w, run.stats);
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
    playEditLog(); // the log's lines at the frame reached, after what the frame recorded
    // (before the lesson's watch sees the frame: lesson_runner plays a step's edits so)
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

void SimulationSession::cycleMethod() {
    const int count = static_cast<int>(Method::Count);
    const int next = (static_cast<int>(world().settings.method) + 1) % count;
    apply(Edit::setWorld("method", methodName(static_cast<Method>(next))));
}

void SimulationSession::applySettings(const WorldSettings& wanted) {
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (row.inScene && !settings_table::same(row, world().settings, wanted))
            apply(Edit::setWorld(row.key, settingJson(row, wanted)));
    }
}

void SimulationSession::setBlockKind(int index, BodyKind kind) {
    if (index < 0 || index >= static_cast<int>(world().blocks.size())) return;
    const Block& b = world().blocks[static_cast<std::size_t>(index)];
    if (b.kind == kind) return;
    // A block made dynamic keeps a mass it had, else gets 1 kg.
    const nlohmann::json mass = kind == BodyKind::Static      ? nlohmann::json("static")
                                : kind == BodyKind::Kinematic ? nlohmann::json("kinematic")
                                : std::isfinite(b.mass)       ? nlohmann::json(b.mass)
                                                              : nlohmann::json(1.0);
    apply(Edit::setBlock({index, ""}, "mass", mass));
}

bool SimulationSession::setBlockSize(int index, Vec2 size) {
    return apply(Edit::setBlock({index, ""}, "size", {size.x, size.y})).empty();
}

int SimulationSession::addBlockAt(Vec2 at) {
    const Vec2 size{1.0, 1.0};
    const auto spot = placeWithoutOverlap(world(), -1, at, size);
    if (!spot) {
        notice = "No room for a new block there";
        return -1;
    }
    const std::string name = "new " + std::to_string(world().blocks.size() + 1);
    if (!apply(Edit::add(
                   {{"name", name}, {"position", {spot->x, spot->y}}, {"size", 1}, {"mass", 1}}))
             .empty())
        return -1;
    selected = static_cast<int>(world().blocks.size()) - 1;
    return selected;
}

void SimulationSession::deleteSelected() {
    const int i = selected;
    if (i < 0 || i >= static_cast<int>(world().blocks.size())) return;
    apply(Edit::remove({i, ""}));
    selected = -1;
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
        // A name whose new mass takes it past the format's limit is saved as it was read.
        if (!limits::textLengthViolation(def.name, limits::kMaxNameChars).empty())
            def.name = labels[i].name;
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
