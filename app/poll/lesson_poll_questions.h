// The poll's questions from a lesson, through the lesson library (lesson_prompt.h): each step's
// question and its choices as the step shows them, and the choice its run proves at the moment.
#pragma once

#include "lesson.h"
#include "lesson_prompt.h"
#include "poll_question.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

// The choice a run proved: the one its event proves (lesson_prompt's StepAnswer::proved), -1 when
// it proves none or more than one.
int provedChoice(const std::vector<int>& proved);
// Step `number`'s (1-based) question as `prompt` says it, proved by `proved` (-1: none); none,
// with `why` ("step 1 asks nothing"), when the step asks nothing to vote on.
std::optional<PollQuestion> pollQuestion(int number, const StepPrompt& prompt, int proved,
                                         std::string* why);
// The questions of `lesson` as written: a step's proved choice is the one its run as written
// proves (run once, when the step is first asked).
PollQuestions lessonPollQuestions(std::shared_ptr<const Lesson> lesson);
// The same from the lesson file at `path` (loaded as the lesson library loads it); none, with
// `error` naming the file and place, when it cannot be read.
std::optional<PollQuestions> lessonPollQuestions(const std::string& path,
                                                 const LessonContext& context, std::string* error);
