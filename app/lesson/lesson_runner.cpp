#include "lesson_runner.h"

#include "edit_history.h"
#include "lesson_guards.h"
#include "printable.h"
#include "scene_json.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace {

// s: a frame ending within this of a time counts as reaching it (frame times are sums of dt and
// carry rounding).
constexpr double kTimeSlack = 1e-9;

std::string formatValue(double x) {
    return scene_json::dumpValue(x);
}

bool reachedTime(const World& world, double time) {
    return world.time >= time - kTimeSlack * std::max(1.0, time);
}

const Block* blockAt(const World& world, int index) {
    return index >= 0 && static_cast<std::size_t>(index) < world.blocks.size()
               ? &world.blocks[static_cast<std::size_t>(index)]
               : nullptr;
}

double sideOf(const Block& b, const std::string& side) {
    if (side == "x") return b.position.x;
    if (side == "y") return b.position.y;
    if (side == "left") return b.position.x - b.halfSize().x;
    if (side == "right") return b.position.x + b.halfSize().x;
    if (side == "bottom") return b.position.y - b.halfSize().y;
    return b.position.y + b.halfSize().y;
}

// The gap between two blocks along an axis (positive: apart), and whether their velocities
// close it.
struct AxisGap {
    double gap = 0.0;
    bool closing = false;
};
AxisGap axisGap(const Block& a, const Block& b, int axis) {
    const double ac = axis == 0 ? a.position.x : a.position.y;
    const double bc = axis == 0 ? b.position.x : b.position.y;
    const double ah = axis == 0 ? a.halfSize().x : a.halfSize().y;
    const double bh = axis == 0 ? b.halfSize().x : b.halfSize().y;
    const double av = axis == 0 ? a.velocity.x : a.velocity.y;
    const double bv = axis == 0 ? b.velocity.x : b.velocity.y;
    AxisGap g;
    g.gap = std::abs(bc - ac) - ah - bh;
    g.closing = (bc > ac ? av - bv : bv - av) > 0.0;
    return g;
}

} // namespace

std::vector<int> liveBlockIndex(const Scene& stepScene, const std::vector<std::string>& liveNames) {
    // Each name of the live world: how many blocks bear it, and the first (one pass, so that a
    // step of 20,000 unnamed blocks costs 20,000 looks, not 20,000 squared).
    struct Bearers {
        std::size_t count = 0, first = 0;
    };
    std::unordered_map<std::string, Bearers> bearers;
    for (std::size_t j = 0; j < liveNames.size(); ++j) {
        Bearers& b = bearers[liveNames[j]];
        if (b.count++ == 0) b.first = j;
    }
    std::vector<int> map(stepScene.blocks.size(), -1);
    for (std::size_t i = 0; i < stepScene.blocks.size(); ++i) {
        const std::string& name = stepScene.blocks[i].name;
        const auto found = name.empty() ? bearers.end() : bearers.find(name);
        if (found != bearers.end() && found->second.count == 1) {
            map[i] = static_cast<int>(found->second.first);
        } else if (i < liveNames.size() && liveNames[i] == name) {
            map[i] = static_cast<int>(i); // unnamed or named twice: where it was
        }
    }
    return map;
}

LessonWatch::LessonWatch(const LessonStep& step, std::vector<int> blocks, double within,
                         double watchSeconds)
    : pause_(step.pause), blocks_(std::move(blocks)), within_(within), watch_(watchSeconds) {
    for (const BlockDef& b : step.scene->blocks) names_.push_back(b.name);
    const auto live = [this](int i) {
        return i >= 0 && static_cast<std::size_t>(i) < blocks_.size()
                   ? blocks_[static_cast<std::size_t>(i)]
                   : -1;
    };
    block_ = live(pause_.block);
    other_ = live(pause_.other);
}

bool LessonWatch::atStart(const World& start) {
    const bool needsBlock = pause_.block >= 0;
    if (needsBlock && (block_ < 0 || (pause_.other >= 0 && other_ < 0))) {
        const std::string& gone = block_ < 0 ? pause_.blockName : pause_.otherName;
        missed_ = printable(gone) + " is no longer in the scene";
        state_ = State::Missed;
        return true;
    }
    if (pause_.kind == LessonPause::Kind::Time && pause_.time <= kTimeSlack) {
        event_ = start;
        state_ = State::Paused;
        return true;
    }
    return false;
}

namespace {

// `r` with its bodies swapped: body 1 becomes body 2.
CollisionRecord swapped(CollisionRecord r) {
    std::swap(r.block, r.other);
    std::swap(r.m1, r.m2);
    std::swap(r.v1, r.v2);
    std::swap(r.v1After, r.v2After);
    std::swap(r.position1, r.position2);
    r.firstBelow = !r.firstBelow;
    return r;
}

} // namespace

bool LessonWatch::eventIn(const World& world, const std::vector<CollisionRecord>& log,
                          int collisionsBefore) {
    using K = LessonPause::Kind;
    switch (pause_.kind) {
    case K::None:
        return false;
    case K::Time:
        return reachedTime(world, pause_.time);
    case K::Collision: {
        if (progress_.collisions < pause_.collision) return false;
        int k = collisionsBefore;
        for (const CollisionRecord& r : log) {
            if (r.rest || ++k < pause_.collision) continue;
            hit_ = r;
            break;
        }
        return true;
    }
    case K::BlockCollision:
    case K::PairCollision:
        for (const CollisionRecord& r : log) {
            if (r.rest) continue;
            const bool mine = r.block == block_ || r.other == block_;
            if (!mine) continue;
            if (pause_.kind == K::PairCollision && r.block != other_ && r.other != other_) continue;
            hit_ = r.block == block_ ? r : swapped(r);
            return true;
        }
        return false;
    case K::Rest: {
        const Block* b = blockAt(world, block_);
        return b && std::hypot(b->velocity.x, b->velocity.y) <= kRestSpeed;
    }
    case K::Reach: {
        const Block* b = blockAt(world, block_);
        if (!b) return false;
        const double at = sideOf(*b, pause_.side);
        return pause_.atLeast ? at >= pause_.at : at <= pause_.at;
    }
    }
    return false;
}

bool LessonWatch::afterFrame(const World& world, const StepStats& stats,
                             const std::vector<CollisionRecord>& log) {
    if (paused()) return true;
    ++progress_.frames;
    const int collisionsBefore = progress_.collisions;
    progress_.maxPenetration = std::max(progress_.maxPenetration, stats.maxPenetration);
    for (const CollisionRecord& r : log) {
        if (r.rest)
            ++progress_.contacts;
        else
            ++progress_.collisions;
    }
    if (state_ == State::Waiting && pause_.kind != LessonPause::Kind::None &&
        eventIn(world, log, collisionsBefore)) {
        event_ = world;
        eventProgress_ = progress_;
        eventTime_ = world.time;
        state_ = pause_.kind == LessonPause::Kind::Time ? State::Paused : State::Watching;
        if (state_ == State::Paused) return true;
    }
    if (state_ == State::Watching && reachedTime(world, eventTime_ + watch_)) {
        state_ = State::Paused;
        return true;
    }
    if (state_ == State::Waiting && pause_.kind != LessonPause::Kind::None &&
        pause_.kind != LessonPause::Kind::Time && reachedTime(world, within_)) {
        giveUp(world, whyMissed(world));
        return true;
    }
    return false;
}

void LessonWatch::giveUp(const World& world, const std::string& why) {
    if (state_ == State::Watching) { // the event came; the watch is cut short
        state_ = State::Paused;
        return;
    }
    state_ = State::Missed;
    missed_ = why.empty() ? whyMissed(world) : why;
}

std::string LessonWatch::whyMissed(const World& world) const {
    const std::string in = " in " + formatQuantity(world.time, "s");
    const std::string name = printable(pause_.blockName), other = printable(pause_.otherName);
    const Block* a = blockAt(world, block_);
    const Block* b = blockAt(world, other_);
    using K = LessonPause::Kind;
    switch (pause_.kind) {
    case K::Collision:
        return "only " + std::to_string(progress_.collisions) + " of " +
               std::to_string(pause_.collision) + " collisions" + in;
    case K::BlockCollision:
        return name + " has hit nothing" + in;
    case K::PairCollision: {
        std::string why = name + " has not hit " + other + in;
        if (!a || !b) return why;
        const AxisGap x = axisGap(*a, *b, 0), y = axisGap(*a, *b, 1);
        // To meet along one axis they must overlap along the other (or come to).
        if ((y.gap > 0.0 && !y.closing && x.gap <= 0.0) ||
            (x.gap > 0.0 && !x.closing && y.gap <= 0.0))
            return why + ": they move apart";
        if ((y.gap > 0.0 && !y.closing) || (x.gap > 0.0 && !x.closing))
            return why + ": they are not on one line";
        return why;
    }
    case K::Rest:
        if (!a) return name + " is no longer in the scene";
        return name + " still moves at " +
               formatQuantity(std::hypot(a->velocity.x, a->velocity.y), "m/s") + " after " +
               formatQuantity(world.time, "s");
    case K::Reach:
        if (!a) return name + " is no longer in the scene";
        return name + " has not reached " + pause_.side + (pause_.atLeast ? " >= " : " <= ") +
               formatQuantity(pause_.at, "m") + in + " (" + pause_.side + " = " +
               formatQuantity(sideOf(*a, pause_.side), "m") + ")";
    default:
        return "the pause point was not reached" + in;
    }
}

bool pausesAtItsSetup(const LessonStep& step) {
    return step.pause.kind == LessonPause::Kind::Time && step.pause.time <= kTimeSlack;
}

namespace {

// A step's edits (docs/edits.md), played at their frames as the app plays them: through the one
// door, with their own undo history (a step's "undo" lines), the blocks named by `names`.
class StepEdits {
  public:
    StepEdits(const LessonStep& step, const std::vector<std::string>& names) : player_(step.edits) {
        for (const std::string& name : names) labels_.push_back({name, ""});
    }
    // Passes over the lines at or before `frame` unplayed (a world that is already past them).
    void skipTo(std::uint64_t frame) {
        while (player_.next(frame)) {
        }
    }
    // Plays the lines due at the world's frame; the first refusal, with its place, or "".
    std::string playDue(World& world) {
        while (const LogLine* line = player_.next(world.frame)) {
            const JournalEntry& e = line->entry;
            const EditTarget target{world, labels_};
            EditError error;
            if (e.what == JournalEntry::What::Undo)
                error = history_.undo(target, world.frame).error;
            else if (e.what == JournalEntry::What::Redo)
                error = history_.redo(target, world.frame).error;
            else
                error = history_.apply(target, e.edit, world.frame, e.continues).error;
            if (!error.empty()) return logLineError(*line, error).text();
        }
        return "";
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const BlockLabel& label : labels_) out.push_back(label.name);
        return out;
    }

  private:
    LogPlayer player_;
    std::vector<BlockLabel> labels_;
    EditHistory history_;
};

std::vector<std::string> sceneNames(const Scene& scene) {
    std::vector<std::string> names;
    for (const BlockDef& b : scene.blocks) names.push_back(b.name);
    return names;
}

// The step's scene with its edits at frame 0 played (`edits` goes on from there); `refused`: the
// first of them refused, or "".
World startWithEdits(const LessonStep& step, StepEdits& edits, std::string& refused) {
    World world = makeWorld(*step.scene);
    refused = edits.playDue(world);
    return world;
}

} // namespace

World stepStartWorld(const LessonStep& step) {
    StepEdits edits(step, sceneNames(*step.scene));
    std::string refused;
    return startWithEdits(step, edits, refused);
}

namespace {

StepRun runWatched(const LessonStep& step, World start, LessonWatch watch, int limit,
                   StepEdits& edits, std::string editError) {
    const World setup = start;
    World world = std::move(start);
    if (editError.empty() && !watch.atStart(world) && step.pause.kind != LessonPause::Kind::None) {
        std::vector<CollisionRecord> log;
        while (!watch.paused()) {
            if (watch.progress().frames >= limit) {
                watch.giveUp(world, "");
                break;
            }
            log.clear();
            const StepStats stats =
                step.scene->player
                    ? stepWithPlayer(world, *step.scene->player,
                                     scriptedKeys(step.input, world.time, world.settings.dt), &log)
                    : world.step(&log);
            // The edits due at the frame reached, after what it did (as the app's session).
            editError = edits.playDue(world);
            if (!editError.empty()) break; // the run stops at a refused edit
            watch.afterFrame(world, stats, log);
        }
    }
    StepRun run = watchedRun(watch, setup, world);
    if (step.pause.kind == LessonPause::Kind::None) run.reached = true; // it stays at its start
    run.editError = std::move(editError);
    return run;
}

StepRun runEdited(const LessonStep& step, World start, StepEdits& edits, std::string editError,
                  double within, double timeScale) {
    LessonWatch watch(step, liveBlockIndex(*step.scene, edits.names()), within,
                      step.pause.watch * timeScale);
    const int limit = frameLimit(step, start, within, timeScale);
    return runWatched(step, std::move(start), std::move(watch), limit, edits, std::move(editError));
}

} // namespace

StepRun runStepToPause(const LessonStep& step) {
    const double within = step.pause.within.value_or(lesson_guards::kCollisionSearchSeconds);
    StepEdits edits(step, sceneNames(*step.scene));
    std::string refused;
    World start = startWithEdits(step, edits, refused);
    return runEdited(step, std::move(start), edits, std::move(refused), within, step.timeScale);
}

StepRun runStepFrom(const LessonStep& step, World start, const std::vector<std::string>& names,
                    double within, double timeScale) {
    StepEdits edits(step, names);
    edits.skipTo(start.frame); // those up to the start are in it
    return runEdited(step, std::move(start), edits, "", within, timeScale);
}

int frameLimit(const LessonStep& step, const World& start, double within, double timeScale) {
    const double dt = start.settings.dt;
    const double seconds = step.pause.kind == LessonPause::Kind::Time
                               ? step.pause.time * 1.01 + 1.0
                               : within + step.pause.watch * timeScale;
    const double perFrame = static_cast<double>(std::max<std::size_t>(1, start.blocks.size())) *
                            std::max(1, start.settings.substeps);
    const double limit =
        std::min(std::ceil(seconds / dt) + 2, std::floor(kMaxStepBlockSteps / perFrame));
    return static_cast<int>(std::max(1.0, limit));
}

StepRun watchedRun(const LessonWatch& watch, const World& setup, const World& now) {
    StepRun run;
    run.setup = setup;
    run.world = now;
    run.blocks = watch.blocks();
    run.progress = watch.progress();
    run.reached = watch.state() == LessonWatch::State::Paused;
    run.missed = watch.missed();
    if (watch.eventWorld()) {
        run.event = *watch.eventWorld();
        run.eventProgress = watch.eventProgress();
        run.hit = watch.hit();
    } else {
        run.event = now; // no event: where the run is (nothing is claimed of it)
        run.eventProgress = run.progress;
    }
    return run;
}

double liveWithin(const LessonStep& step, const StepRun& asWritten) {
    if (step.pause.within) return *step.pause.within;
    return std::max(2.0 * asWritten.world.time, 1.0);
}

ExprScope eventScope(const LessonStep& step, const StepRun& run) {
    ExprScope s;
    s.setup = &run.setup;
    s.now = &run.event;
    s.collisions = run.eventProgress.collisions;
    s.contacts = run.eventProgress.contacts;
    s.maxPenetration = run.eventProgress.maxPenetration;
    s.values = &step.values;
    s.blocks = &run.blocks;
    s.hit = run.hit ? &*run.hit : nullptr;
    return s;
}

ExprScope setupScope(const LessonStep& step, const World& setup, const std::vector<int>& blocks) {
    ExprScope s;
    s.setup = &setup;
    s.now = &setup;
    s.values = &step.values;
    s.blocks = &blocks;
    return s;
}

double measure(const LessonExpect& e, const StepRun& run) {
    const World& w = run.event;
    const StepProgress& progress = run.eventProgress;
    const int live = e.block >= 0 && static_cast<std::size_t>(e.block) < run.blocks.size()
                         ? run.blocks[static_cast<std::size_t>(e.block)]
                         : e.block;
    const Block* b = blockAt(w, live);
    using Q = LessonExpect::Quantity;
    switch (e.quantity) {
    case Q::X:
        return b ? b->position.x : NAN;
    case Q::Y:
        return b ? b->position.y : NAN;
    case Q::Vx:
        return b ? b->velocity.x : NAN;
    case Q::Vy:
        return b ? b->velocity.y : NAN;
    case Q::Time:
        return w.time;
    case Q::Collisions:
        return progress.collisions;
    case Q::MomentumX:
        return totalMomentum(w).x;
    case Q::MomentumY:
        return totalMomentum(w).y;
    case Q::KineticEnergy:
        return kineticEnergy(w);
    case Q::MaxPenetration:
        return progress.maxPenetration;
    case Q::Left:
        return b ? b->position.x - b->halfSize().x : NAN;
    case Q::Right:
        return b ? b->position.x + b->halfSize().x : NAN;
    case Q::Bottom:
        return b ? b->position.y - b->halfSize().y : NAN;
    case Q::Top:
        return b ? b->position.y + b->halfSize().y : NAN;
    case Q::Mass:
        return b ? b->mass : NAN;
    case Q::FrameRate:
        return 1.0 / w.settings.dt;
    case Q::Bounciness:
        return w.settings.bounciness;
    }
    return NAN;
}

std::vector<int> provedChoices(const LessonStep& step, const StepRun& run) {
    std::vector<int> proved;
    if (!run.reached) return proved;
    const ExprScope scope = eventScope(step, run);
    for (std::size_t i = 0; i < step.choices.size(); ++i)
        if (holds(step.choices[i].when, scope)) proved.push_back(static_cast<int>(i));
    return proved;
}

namespace {

// One message per expectation of `expects` that `run` does not meet.
void checkExpects(const std::vector<LessonExpect>& expects, const StepRun& run, bool atSetup,
                  std::vector<std::string>& failures) {
    for (const LessonExpect& e : expects) {
        const double value = measure(e, run);
        const bool ok = e.equals ? std::abs(value - *e.equals) <= e.tolerance
                                 : (!e.min || value >= *e.min) && (!e.max || value <= *e.max);
        if (ok && std::isfinite(value)) continue;
        std::string what = quantityName(e.quantity);
        if (e.block >= 0) what += " of \"" + printable(e.blockName) + "\"";
        std::string expected;
        if (e.equals) {
            expected = formatValue(*e.equals) + " within " + formatValue(e.tolerance);
        } else {
            expected = std::string("in [") + (e.min ? formatValue(*e.min) : "-inf") + ", " +
                       (e.max ? formatValue(*e.max) : "inf") + "]";
        }
        const std::string when = atSetup ? "at the setup, t = 0"
                                         : "at t = " + formatValue(run.event.time) + " s, frame " +
                                               std::to_string(run.eventProgress.frames);
        failures.push_back(printable(e.where, kPrintablePath) + ": " + what + " is " +
                           formatValue(value) + ", expected " + expected + " (" + when + ")");
    }
}

} // namespace

std::vector<std::string> checkSetup(const LessonStep& step) {
    std::vector<std::string> failures;
    StepRun setup;
    setup.setup = stepStartWorld(step);
    setup.world = setup.setup;
    setup.event = setup.setup;
    checkExpects(step.given, setup, true, failures);
    return failures;
}

std::vector<std::string> checkStep(const LessonStep& step, const StepRun& run) {
    std::vector<std::string> failures = checkSetup(step);
    if (!run.editError.empty()) { // its run stopped there
        failures.push_back(run.editError);
        return failures;
    }
    const std::string place = printable(step.place, kPrintablePath);
    if (!run.reached) {
        // Where it gave up: the search's end, or the step's budget of block-steps.
        const double searched = static_cast<double>(run.progress.frames);
        failures.push_back(place + ".pause_at: the pause point was not reached in " +
                           std::to_string(run.progress.frames) +
                           " frames (t = " + formatValue(run.world.time) + " s; " +
                           (searched >= pauseFrames(step)
                                ? "the search ends after " +
                                      formatValue(step.pause.within.value_or(
                                          lesson_guards::kCollisionSearchSeconds)) +
                                      " s"
                                : "a step may run 1e8 block-steps") +
                           "): " + run.missed);
        return failures;
    }
    checkExpects(step.expect, run, false, failures);
    if (step.choices.empty()) return failures;
    const std::vector<int> proved = provedChoices(step, run);
    for (std::size_t i = 0; i < step.choices.size(); ++i) {
        const bool isProved =
            std::find(proved.begin(), proved.end(), static_cast<int>(i)) != proved.end();
        const bool isCorrect = static_cast<int>(i) == step.correct;
        if (isProved == isCorrect) continue;
        failures.push_back(
            place + ".choices[" + std::to_string(i) + "]: choice " + choiceLetter(i) +
            (isCorrect ? " is marked correct, but the run "
                         "contradicts it: "
                       : " is not the correct one, but the run "
                         "proves it too: ") +
            printable(step.choices[i].when.source) + " is " + (isProved ? "true" : "false") +
            " at t = " + formatValue(run.event.time) + " s");
    }
    return failures;
}

std::vector<std::string> checkLesson(const Lesson& lesson) {
    std::vector<std::string> failures;
    for (const LessonStep& step : lesson.steps) {
        const std::vector<std::string> f = checkStep(step, runStepToPause(step));
        failures.insert(failures.end(), f.begin(), f.end());
    }
    return failures;
}
