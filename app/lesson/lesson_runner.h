// Runs a lesson step headless, through the engine only: the world the step states, stepped frame
// by frame to its pause point, and its expectations checked there. The app enters a step the same
// way (makeWorld of the step's scene, then World::step per frame), so what ctest checks is what
// the lecturer sees.
#pragma once

#include "lesson.h"

#include <string>
#include <vector>

// What the pause point and the expectations count, frame by frame since the step began.
struct StepProgress {
    int frames = 0;
    int collisions = 0;         // resolved collisions, walls included, rest-rule contacts not
    int contacts = 0;           // resting contacts resolved by the rest rule (counted apart)
    double maxPenetration = 0.; // m
    bool blockCollided = false; // LessonPause::BlockCollision's block has collided
};

// Counts one frame (its stats and collision log) into `progress`; true when the pause point is
// reached at the end of this frame.
bool countFrame(const LessonPause& pause, const World& world, const StepStats& stats,
                const std::vector<CollisionRecord>& log, StepProgress& progress);
// True when the pause point holds before any frame (a pause at time 0).
bool pausesAtStart(const LessonPause& pause);

struct StepRun {
    World world; // at the pause point (or where the runner gave up)
    StepProgress progress;
    bool reached = true; // false: the pause point never came within maxStepFrames()
    std::string
        editError; // a step's edit refused on the way ("lesson.json: steps[2].edits[0]: ...")
};

// The world exactly as the step states it (the same every time the step is entered): its scene
// with its edits at frame 0.
World stepStartWorld(const LessonStep& step);
// Runs the step from its start to its pause point (no pause point: stays at the start).
StepRun runStepToPause(const LessonStep& step);

// The measured value of an expectation in a run.
double measure(const LessonExpect& e, const StepRun& run);
// Checks what the step's question states of its setup (`given`) at t = 0, before any frame.
std::vector<std::string> checkSetup(const LessonStep& step);
// Checks the step's `given` at its setup and every expectation at its pause point; one message
// per failure ("lesson.json: steps[3].expect[0]:
// vx of "m1" is -1.5, expected -2 within 1e-09"), and one if the pause point was not reached.
std::vector<std::string> checkStep(const LessonStep& step, const StepRun& run);
// Every step of the lesson, in order: all failure messages.
std::vector<std::string> checkLesson(const Lesson& lesson);
