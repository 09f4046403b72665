// What a step says to the class, for the world as it is (docs/lesson-format.md, "Computed text"):
// its question and lettered choices at the setup, and at the moment the answer the run gives, or,
// when the event did not come, why not (and no answer). The caption bar, the screen reader, the
// class poll and `sandbox-cli lesson` all read these. No GL, no ImGui.
#pragma once

#include "lesson_runner.h"

#include <string>
#include <vector>

// The question and its choices, as the setup shows them.
struct StepPrompt {
    std::string caption;              // the slide's point
    std::string question;             // "" when the step asks nothing
    std::vector<std::string> choices; // the choices' texts, in order (lettered A-D when shown)
    int correct = -1;                 // the choice the step as written proves
};
// `setup`: the world at the setup (the lecturer's, or stepStartWorld); `blocks`: liveBlockIndex
// of it; `asWritten`: the world is the step as written ({as written: ...} parts stand as they
// are).
StepPrompt stepPrompt(const LessonStep& step, const World& setup, const std::vector<int>& blocks,
                      bool asWritten);
StepPrompt stepPrompt(const LessonStep& step); // as written

// The answer at the moment.
struct StepAnswer {
    bool reached = false;    // the event came: `text` is the answer
    std::vector<int> proved; // the choices the run proves (their conditions hold at the event)
    // "B. v' = -C·v = -0.5·4 = -2 m/s ..."; with the lecturer's changes "With C = 0.9: B. ...
    // As written (C = 0.5): B, -2 m/s and 2 J."; "" when the event did not come.
    std::string text;
    std::string missed; // why the event did not come ("m1 has not hit m2 in 1.75 s: ...")
};
// `changes`: what the lecturer changed, as the answer says it ("C = 0.9", "m2's mass = 4 kg");
// empty: the step as written. `asWritten`: the step's run as written (for the result beside a
// changed one; may be null).
StepAnswer stepAnswer(const LessonStep& step, const StepRun& run,
                      const std::vector<std::string>& changes, const StepRun* asWritten);

// What the lecturer changed of the step's setup as written, as the answer says it: the settings
// by their symbol or name ("C = 0.9", "frame rate 60 Hz", "method turn-based"), then each block
// the step names ("m2's mass 4 kg", "m2 moved to (7, 6) m", "m1's velocity (3, 0) m/s", "m2's
// size 2 x 1 m", "m2 deleted"), then blocks added ("1 block added"). `now`: the lecturer's world
// at its setup; `blocks`: liveBlockIndex of it; `written`: stepStartWorld(step). Empty: the same.
std::vector<std::string> setupChanges(const LessonStep& step, const World& now,
                                      const std::vector<int>& blocks, const World& written);

// "A", "A and C", "A, B and D".
std::string choiceLetters(const std::vector<int>& choices);
