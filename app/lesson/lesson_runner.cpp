#include "lesson_runner.h"

#include "edit_history.h"

#include "printable.h"
#include "scene_json.h"

#include <algorithm>
#include <cmath>

namespace {

// s: a frame ending within this of the pause time counts as reaching it (frame times are sums of
// dt and carry rounding).
constexpr double kTimeSlack = 1e-9;

std::string formatNumber(double x) {
    return scene_json::dumpValue(x);
}

} // namespace

bool pausesAtStart(const LessonPause& pause) {
    return pause.kind == LessonPause::Kind::Time && pause.time <= kTimeSlack;
}

bool countFrame(const LessonPause& pause, const World& world, const StepStats& stats,
                const std::vector<CollisionRecord>& log, StepProgress& progress) {
    ++progress.frames;
    progress.maxPenetration = std::max(progress.maxPenetration, stats.maxPenetration);
    bool blockHit = false;
    for (const CollisionRecord& r : log) {
        if (r.rest) {
            ++progress.contacts;
            continue;
        }
        ++progress.collisions;
        if (r.block == pause.block || r.other == pause.block) blockHit = true;
    }
    switch (pause.kind) {
    case LessonPause::Kind::None:
        return false;
    case LessonPause::Kind::Time:
        return world.time >= pause.time - kTimeSlack * std::max(1.0, pause.time);
    case LessonPause::Kind::Collision:
        return progress.collisions >= pause.collision;
    case LessonPause::Kind::BlockCollision:
        if (pause.block >= 0 && blockHit) progress.blockCollided = true;
        return progress.blockCollided;
    }
    return false;
}

namespace {

// A step's world and its edits (docs/edits.md), played at their frames as the app plays them.
struct EditedStep {
    World& world;
    std::vector<BlockLabel> labels;
    EditHistory history;
    LogPlayer player;
    EditedStep(World& w, const LessonStep& step) : world(w), player(step.edits) {
        for (const BlockDef& def : step.scene->blocks) labels.push_back({def.name, def.color});
    }
    // The lines due at the world's frame; the first refusal, or "".
    std::string playDue() {
        while (const LogLine* line = player.next(world.frame)) {
            const JournalEntry& e = line->entry;
            const EditTarget target{world, labels};
            EditError error;
            if (e.what == JournalEntry::What::Undo)
                error = history.undo(target, world.frame).error;
            else if (e.what == JournalEntry::What::Redo)
                error = history.redo(target, world.frame).error;
            else
                error = history.apply(target, e.edit, world.frame, e.continues).error;
            if (!error.empty()) return logLineError(*line, error).text();
        }
        return "";
    }
};

} // namespace

World stepStartWorld(const LessonStep& step) {
    World world = makeWorld(*step.scene);
    EditedStep(world, step).playDue();
    return world;
}

StepRun runStepToPause(const LessonStep& step) {
    StepRun run;
    run.world = makeWorld(*step.scene);
    EditedStep edited(run.world, step);
    run.editError = edited.playDue();
    if (step.pause.kind == LessonPause::Kind::None || pausesAtStart(step.pause)) return run;
    const int limit = maxStepFrames(step);
    std::vector<CollisionRecord> log;
    while (run.progress.frames < limit && run.editError.empty()) {
        log.clear();
        const StepStats stats =
            step.scene->player
                ? stepWithPlayer(run.world, *step.scene->player,
                                 scriptedKeys(step.input, run.world.time, run.world.settings.dt),
                                 &log)
                : run.world.step(&log);
        run.editError = edited.playDue();
        if (countFrame(step.pause, run.world, stats, log, run.progress)) return run;
    }
    run.reached = false;
    return run;
}

double measure(const LessonExpect& e, const StepRun& run) {
    const World& w = run.world;
    const Block* b = e.block >= 0 && e.block < static_cast<int>(w.blocks.size())
                         ? &w.blocks[static_cast<std::size_t>(e.block)]
                         : nullptr;
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
        return run.progress.collisions;
    case Q::MomentumX:
        return totalMomentum(w).x;
    case Q::MomentumY:
        return totalMomentum(w).y;
    case Q::KineticEnergy:
        return kineticEnergy(w);
    case Q::MaxPenetration:
        return run.progress.maxPenetration;
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
            expected = formatNumber(*e.equals) + " within " + formatNumber(e.tolerance);
        } else {
            expected = std::string("in [") + (e.min ? formatNumber(*e.min) : "-inf") + ", " +
                       (e.max ? formatNumber(*e.max) : "inf") + "]";
        }
        const std::string when = atSetup ? "at the setup, t = 0"
                                         : "at t = " + formatNumber(run.world.time) + " s, frame " +
                                               std::to_string(run.progress.frames);
        failures.push_back(printable(e.where, kPrintablePath) + ": " + what + " is " +
                           formatNumber(value) + ", expected " + expected + " (" + when + ")");
    }
}

} // namespace

std::vector<std::string> checkSetup(const LessonStep& step) {
    std::vector<std::string> failures;
    StepRun setup{stepStartWorld(step), StepProgress{}, true, ""};
    checkExpects(step.given, setup, true, failures);
    return failures;
}

std::vector<std::string> checkStep(const LessonStep& step, const StepRun& run) {
    std::vector<std::string> failures = checkSetup(step);
    if (!run.editError.empty()) { // its run stopped there
        failures.push_back(run.editError);
        return failures;
    }
    if (!run.reached) {
        // Where it gave up: the collision search's end, or the step's budget of block-steps.
        const double searched = static_cast<double>(run.progress.frames);
        failures.push_back(printable(step.place, kPrintablePath) +
                           ".pause_at: the pause point was not reached in " +
                           std::to_string(run.progress.frames) +
                           " frames (t = " + formatNumber(run.world.time) + " s; " +
                           (searched >= pauseFrames(step) ? "the search ends after 120 s"
                                                          : "a step may run 1e8 block-steps") +
                           ")");
        return failures;
    }
    checkExpects(step.expect, run, false, failures);
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
