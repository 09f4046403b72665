// What a screen reader is told about the screen (the browser's page puts it in the DOM beside the
// canvas): the scene, the lesson's step and the status; the collisions are collision_announcer.h's.
// Plain logic from the app's state, no ImGui: tested in tests/app.
#pragma once

#include <string>

struct App;

// The texts the canvas shows, as sentences.
struct SpokenScreen {
    std::string scene;       // the scene's name
    std::string description; // the scene's description
    std::string lesson;      // "Lesson: Lecture 3, step 3 of 24: title"; "" without a lesson
    // The caption bar's lines (lessonCaption, each on one line): the step's caption,
    // "Predict: " and its question while it waits for its answer, "Answer: " and the answer
    // once revealed (then no question, as on the bar).
    std::string caption;
    std::string question;
    std::string answer;
    std::string status; // "perfect method, t = 0.62 s, paused, 1 collision"
    bool operator==(const SpokenScreen& o) const;
    bool operator!=(const SpokenScreen& o) const { return !(*this == o); }
};
SpokenScreen spokenScreen(const App& app);
