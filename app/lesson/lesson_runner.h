// Runs a lesson step headless, through the engine only: the world the step states (or the one the
// lecturer made of it), stepped frame by frame until its event (docs/lesson-format.md,
// "pause_at"), then on for the watch, and its expectations and choices checked at the event. The
// app runs a step the same way (makeWorld of the step's scene, World::step per frame, and a
// LessonWatch told of every frame), so what ctest checks is what the lecturer sees.
#pragma once

#include "lesson.h"

#include <optional>
#include <string>
#include <vector>

// What the pause point and the expectations count, frame by frame since the step began.
struct StepProgress {
    int frames = 0;
    int collisions = 0;         // resolved collisions, walls included, rest-rule contacts not
    int contacts = 0;           // resting contacts resolved by the rest rule (counted apart)
    double maxPenetration = 0.; // m
};

// Where the step's blocks are in a live world: the step's block i (its scene's order) is the
// world's block map[i], -1 when the world has no block of that name any more (the lecturer
// deleted it). Blocks are found by name; a block without a unique name keeps its index.
std::vector<int> liveBlockIndex(const Scene& stepScene, const std::vector<std::string>& liveNames);

// A step's event, watched frame by frame: the runner and the app tell it of every frame.
class LessonWatch {
  public:
    enum class State {
        Waiting,  // the event has not come
        Watching, // it came: the motion goes on for the watch
        Paused,   // the moment: pause at the end of this frame, the answer shows
        Missed,   // the event did not come within its time: pause there, no answer
    };
    // `blocks`: liveBlockIndex of the world the run starts from; `within`: s of simulated time the
    // event may take (the world's clock); `watchSeconds`: s of simulated time after the event
    // (the watch times the time scale).
    LessonWatch(const LessonStep& step, std::vector<int> blocks, double within,
                double watchSeconds);
    // Before any frame: true when the run pauses at its start (a time of 0, or an event about a
    // block that is gone: Missed).
    bool atStart(const World& start);
    // After each frame (its stats and collision log): true when the run pauses at its end.
    bool afterFrame(const World& world, const StepStats& stats,
                    const std::vector<CollisionRecord>& log);
    // Gives up where the run is (the runner's budget of frames is spent).
    void giveUp(const World& world, const std::string& why);

    State state() const { return state_; }
    bool paused() const { return state_ == State::Paused || state_ == State::Missed; }
    const StepProgress& progress() const { return progress_; }
    // At the event (from Watching on): the world and what was counted up to it.
    const std::optional<World>& eventWorld() const { return event_; }
    const StepProgress& eventProgress() const { return eventProgress_; }
    // The collision the event is (collision events), body 1 the block the event names.
    const std::optional<CollisionRecord>& hit() const { return hit_; }
    // Why the event did not come, in words ("m1 has not hit m2 in 1.75 s: they are not on one
    // line"); "" unless Missed.
    const std::string& missed() const { return missed_; }
    const std::vector<int>& blocks() const { return blocks_; }
    double within() const { return within_; }

  private:
    bool eventIn(const World& world, const std::vector<CollisionRecord>& log, int collisionsBefore);
    std::string whyMissed(const World& world) const;
    LessonPause pause_;
    std::vector<std::string> names_; // the step's block names, for the words
    std::vector<int> blocks_;
    int block_ = -1, other_ = -1; // the event's blocks in the live world
    double within_, watch_;
    State state_ = State::Waiting;
    StepProgress progress_, eventProgress_;
    std::optional<World> event_;
    std::optional<CollisionRecord> hit_;
    double eventTime_ = 0.0;
    std::string missed_;
};

struct StepRun {
    World setup;           // as the run started
    World world;           // at the pause (after the watch), or where it gave up
    StepProgress progress; // counted up to the pause
    bool reached = true;   // false: the event never came (missed says why)
    // At the event (what the answer, the choices and `expect` read); the pause for a time.
    World event;
    StepProgress eventProgress;
    std::optional<CollisionRecord> hit; // the event's collision (LessonWatch::hit)
    std::string missed;
    std::vector<int> blocks; // liveBlockIndex of the run's world
    // A step's edit refused on the way ("lesson.json: steps[2].edits[0]: ..."): the run stopped.
    std::string editError;
};

// True when the step's moment is its setup (a time of 0): it pauses before any frame.
bool pausesAtItsSetup(const LessonStep& step);

// The world exactly as the step states it (the same every time the step is entered): its scene
// with its edits at frame 0.
World stepStartWorld(const LessonStep& step);
// Runs the step as written from its start to its pause point (an event is searched for within
// its `within`, else 120 s). No pause point: stays at the start.
StepRun runStepToPause(const LessonStep& step);
// Runs the step from `start`, the world the lecturer made of it (`names`: its blocks' names), the
// event searched for within `within` s, watched for `watch` s at `timeScale`; the step's edits
// after `start`'s frame play at their frames, as the app plays them.
StepRun runStepFrom(const LessonStep& step, World start, const std::vector<std::string>& names,
                    double within, double timeScale);
// The frames a run from `start` may take before it gives up: the event's search (`within`) and the
// watch at `timeScale`, within the step's budget of kMaxStepBlockSteps block-steps.
int frameLimit(const LessonStep& step, const World& start, double within, double timeScale);
// What a watch saw, as a run: `setup` the world it started from, `now` the world where it is.
StepRun watchedRun(const LessonWatch& watch, const World& setup, const World& now);
// The time a changed run gives the event: the step's `within`, else twice the moment of the step
// as written (`asWritten`: its run), at least 1 s.
double liveWithin(const LessonStep& step, const StepRun& asWritten);

// What the step's expressions read at the run's event (its setup, now = the event).
ExprScope eventScope(const LessonStep& step, const StepRun& run);
// What the question and the choices read: the setup, before any frame.
ExprScope setupScope(const LessonStep& step, const World& setup, const std::vector<int>& blocks);

// Block `index` of `world`, or null when there is none.
inline const Block* blockAt(const World& world, int index) {
    return index >= 0 && static_cast<std::size_t>(index) < world.blocks.size()
               ? &world.blocks[static_cast<std::size_t>(index)]
               : nullptr;
}

// The measured value of an expectation in a run, at its event.
double measure(const LessonExpect& e, const StepRun& run);
// The choices the run proves: those whose condition holds at its event (none when it missed).
std::vector<int> provedChoices(const LessonStep& step, const StepRun& run);
// Checks what the step's question states of its setup (`given`) at t = 0, before any frame.
std::vector<std::string> checkSetup(const LessonStep& step);
// Checks the step's `given` at its setup, every expectation at its event, and that the run proves
// its correct choice and no other; one message per failure ("lesson.json: steps[3].expect[0]:
// vx of "m1" is -1.5, expected -2 within 1e-09"), and one if the event did not come.
std::vector<std::string> checkStep(const LessonStep& step, const StepRun& run);
// Every step of the lesson, in order: all failure messages.
std::vector<std::string> checkLesson(const Lesson& lesson);
