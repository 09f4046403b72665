// What a screen reader is told about the screen (the browser's page puts it in the DOM beside the
// canvas): the scene, the lesson's step and the status; the collisions are collision_announcer.h's.
// Plain logic from the app's state, no ImGui: tested in tests/app.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct App;

// The texts the canvas shows, as sentences.
struct SpokenScreen {
    std::string scene;       // the scene's name
    std::string description; // the scene's description
    std::string lesson;      // "Lesson: Lecture 3, step 3 of 24: title"; "" without a lesson
    // The caption bar's lines (lessonCaption), each on one line: the step's caption; "Predict: "
    // and its question with its choices ("A. ... B. ...") until the moment; "Answer: " and the
    // answer once revealed, or "No answer: " and why.
    std::string caption;
    std::string question;
    std::string answer;
    std::string status; // "perfect method, t = 0.62 s, paused, 1 collision"
    std::string error;  // the error the app shows, "" for none
    // The changes made through the door so far (SimulationSession::changes) and the last, as a
    // sentence ("bounciness C is now 0.90").
    std::uint64_t changes = 0;
    std::string changed;
    bool operator==(const SpokenScreen& o) const;
    bool operator!=(const SpokenScreen& o) const { return !(*this == o); }
};
SpokenScreen spokenScreen(const App& app);

// What the live region says when the screen changes from `before` to `now` (issue 38: a screen
// reader hears every step change, the answer at the moment and every error): a step entered
// ("Step 3 of 27: title. Predict: ... A. ... B. ..."), its answer once revealed ("Answer: ..."
// or "No answer: ...": as the caption bar says them), an error when one appears ("Error: ..."). One
// line each, in that order; none when nothing of that changed. A change the lecturer made in the
// step (a setting, a block, an undo) that changes its question or answer is said as the change
// and what now reads otherwise: "bounciness C is now 0.90; the question now reads: Predict: ...".
std::vector<std::string> spokenChanges(const SpokenScreen& before, const SpokenScreen& now);
