// The poll's questions from a lesson file: each step's "question", its "choices" (2 to 4) and
// the one the run proves. Until the lesson library lists the choices itself, they are read from
// the file as written: a step's "choices" (strings) and "proved" (an index).
#pragma once

#include "poll_question.h"

#include <optional>
#include <string>

// The questions of the lesson at `path`; none, with `error` naming the file and place, when it
// cannot be read.
std::optional<PollQuestions> lessonPollQuestions(const std::string& path, std::string* error);
