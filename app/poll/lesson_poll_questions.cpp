#include "lesson_poll_questions.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <memory>
#include <sstream>

namespace {

std::optional<PollQuestion> stepQuestion(const nlohmann::json& step, int number,
                                         std::string* error) {
    auto fail = [&](const std::string& why) -> std::optional<PollQuestion> {
        if (error) *error = "step " + std::to_string(number) + " " + why;
        return std::nullopt;
    };
    const auto question = step.find("question");
    if (question == step.end() || !question->is_string() || question->get<std::string>().empty())
        return fail("asks nothing");
    const auto choices = step.find("choices");
    if (choices == step.end() || !choices->is_array()) return fail("has no choices to vote on");
    PollQuestion q;
    q.step = number;
    q.question = question->get<std::string>();
    for (const nlohmann::json& c : *choices) {
        if (!c.is_string()) return fail("has a choice that is not text");
        q.choices.push_back(c.get<std::string>());
    }
    const int n = static_cast<int>(q.choices.size());
    if (n < kMinPollChoices || n > kMaxPollChoices)
        return fail("has " + std::to_string(n) + " choices (2 to 4 can be voted on)");
    if (const auto proved = step.find("proved"); proved != step.end()) {
        if (!proved->is_number_integer() || proved->get<long long>() < 0 ||
            proved->get<long long>() >= n)
            return fail("proves no choice of its own (\"proved\": 0 to " + std::to_string(n - 1) +
                        ")");
        q.proved = proved->get<int>();
    }
    return q;
}

} // namespace

std::optional<PollQuestions> lessonPollQuestions(const std::string& path, std::string* error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (error) *error = path + ": cannot open the lesson";
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    nlohmann::json lesson = nlohmann::json::parse(text.str(), nullptr, false);
    if (lesson.is_discarded() || !lesson.is_object() || !lesson.contains("steps") ||
        !lesson["steps"].is_array()) {
        if (error) *error = path + ": not a lesson (a JSON object with \"steps\")";
        return std::nullopt;
    }
    auto steps = std::make_shared<const nlohmann::json>(std::move(lesson["steps"]));
    return PollQuestions([steps, path](int step, std::string* why) -> std::optional<PollQuestion> {
        const int count = static_cast<int>(steps->size());
        if (step < 1 || step > count) {
            if (why)
                *why = path + ": no step " + std::to_string(step) + ": the lesson has " +
                       std::to_string(count);
            return std::nullopt;
        }
        const nlohmann::json& s = (*steps)[static_cast<std::size_t>(step - 1)];
        if (!s.is_object()) {
            if (why) *why = path + ": steps[" + std::to_string(step - 1) + "] is not an object";
            return std::nullopt;
        }
        std::string reason;
        std::optional<PollQuestion> q = stepQuestion(s, step, &reason);
        if (!q && why) *why = path + ": " + reason;
        return q;
    });
}
