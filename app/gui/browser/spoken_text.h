// What a screen reader is told about the screen (the browser's page puts it in the DOM beside the
// canvas): the scene, the lesson's step and the status; the collisions are collision_announcer.h's.
// Plain logic from the app's state, no ImGui: tested in tests/app.
#pragma once

#include <string>
#include <vector>

struct App;

// The texts the canvas shows, as sentences.
struct SpokenScreen {
    std::string scene;       // the scene's name
    std::string description; // the scene's description
    std::string lesson;      // "Lesson: Lecture 3, step 3 of 24: title"; "" without a lesson
    std::string caption;     // the step's caption (its lines joined)
    std::string question;    // the step's question, while it waits for its answer
    std::string answer;      // the answer, once revealed
    std::string status;      // "perfect method, t = 0.62 s, paused, 1 collision"
    std::string error;       // the error the app shows, "" for none
    bool operator==(const SpokenScreen& o) const;
    bool operator!=(const SpokenScreen& o) const { return !(*this == o); }
};
SpokenScreen spokenScreen(const App& app);

// What the live region says when the screen changes from `before` to `now` (issue 38: a screen
// reader hears every step change, the answer at the moment and every error): a step entered
// ("Step 3 of 27: title. Question: ... A. ... B. ..."), its answer once revealed ("Answer: ..."
// or "No answer: ..."), an error when one appears ("Error: ..."). One line each, in that order;
// none when nothing of that changed.
std::vector<std::string> spokenChanges(const SpokenScreen& before, const SpokenScreen& now);
