// A step's expectations checked against its run (lesson_runner.h: measure, provedChoices,
// checkSetup, checkStep, checkLesson): each failure a sentence naming its place.
#include "lesson_runner.h"

#include "lesson_guards.h"
#include "printable.h"
#include "scene_json.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

std::string formatValue(double x) {
    return scene_json::dumpValue(x);
}

} // namespace

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
