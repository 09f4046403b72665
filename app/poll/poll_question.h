// What the poll asks: a lesson step's question and its lettered choices (2 to 4), and the choice
// the run proves at the step's moment. The poll reads them through PollQuestions, so that where
// they come from (the lesson library, a fixture in a test) is one function.
#pragma once

#include "lesson.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

// As many as a lesson's question has (lesson.h).
inline constexpr int kMinPollChoices = static_cast<int>(kMinChoices);
inline constexpr int kMaxPollChoices = static_cast<int>(kMaxChoices);

struct PollQuestion {
    int step = 0; // 1-based, as the app and `--step` count
    std::string question;
    std::vector<std::string> choices; // kMinPollChoices..kMaxPollChoices, shown as A, B, C, D
    int proved = -1;                  // index into choices; -1: the run proves none of them
};

// The question of step `step` (1-based); none, with `error` saying why ("step 1 asks nothing",
// "no step 40: the lesson has 27"), when the step cannot be polled.
using PollQuestions = std::function<std::optional<PollQuestion>(int step, std::string* error)>;
