#include "lesson_poll_questions.h"

#include "lesson_runner.h"

#include <map>
#include <mutex>

int provedChoice(const std::vector<int>& proved) {
    return proved.size() == 1 ? proved.front() : -1;
}

std::optional<PollQuestion> pollQuestion(int number, const StepPrompt& prompt, int proved,
                                         std::string* why) {
    if (prompt.question.empty() || prompt.choices.size() < kMinChoices) {
        if (why) *why = "step " + std::to_string(number) + " asks nothing to vote on";
        return std::nullopt;
    }
    PollQuestion q;
    q.step = number;
    q.question = prompt.question;
    q.choices = prompt.choices;
    q.proved = proved;
    return q;
}

PollQuestions lessonPollQuestions(std::shared_ptr<const Lesson> lesson) {
    // A step's run as written is the same every time: its proved choice is found once.
    struct Proved {
        std::mutex mutex;
        std::map<int, int> byStep;
    };
    auto proved = std::make_shared<Proved>();
    return [lesson, proved](int number, std::string* why) -> std::optional<PollQuestion> {
        const std::optional<std::size_t> index = stepIndex(*lesson, number, why);
        if (!index) return std::nullopt; // "lesson.json: no step 9 (the lesson has steps 1 to 3)"
        const LessonStep& step = lesson->steps[*index];
        const StepPrompt prompt = stepPrompt(step);
        if (prompt.question.empty()) return pollQuestion(number, prompt, -1, why);
        std::lock_guard lock(proved->mutex);
        auto found = proved->byStep.find(number);
        if (found == proved->byStep.end()) {
            const StepRun run = runStepToPause(step);
            found = proved->byStep.emplace(number, provedChoice(provedChoices(step, run))).first;
        }
        return pollQuestion(number, prompt, found->second, why);
    };
}

std::optional<PollQuestions> lessonPollQuestions(const std::string& path,
                                                 const LessonContext& context, std::string* error) {
    LessonResult loaded = loadLessonFile(path, context);
    if (!loaded.lesson) {
        if (error) *error = loaded.error.text();
        return std::nullopt;
    }
    return lessonPollQuestions(std::make_shared<const Lesson>(std::move(*loaded.lesson)));
}
