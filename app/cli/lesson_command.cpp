// sandbox-cli lesson (docs/cli.md): every step of a lesson run to its pause point, as text or JSON.
#include "commands.h"

#include "cli_print.h"

#include "lesson_prompt.h"
#include "lesson_runner.h"
#include "printable.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

namespace {

// A text of several lines as one (its line breaks as spaces), safe to print.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return printable(text, kPrintablePath);
}

std::string blockLabel(const LessonStep& step, std::size_t b) {
    return step.scene->blocks[b].name.empty() ? "#" + std::to_string(b)
                                              : step.scene->blocks[b].name;
}

// One step as `lesson --json` lists it: where it pauses, what it counted, and the seconds of
// motion the class sees from its setup (t = 0) to that moment at its time scale.
nlohmann::ordered_json stepJson(std::size_t number, const LessonStep& step, const StepRun& run,
                                const std::vector<std::string>& failures) {
    nlohmann::ordered_json j;
    j["step"] = number;
    j["title"] = step.title;
    j["method"] = methodName(run.world.settings.method);
    j["reached"] = run.reached;
    j["pause_time"] = run.world.time;
    j["frame"] = run.progress.frames;
    j["collisions"] = run.progress.collisions;
    j["contacts"] = run.progress.contacts;
    j["time_scale"] = step.timeScale;
    j["motion_seconds"] = run.world.time / step.timeScale;
    j["event_time"] =
        run.reached ? nlohmann::ordered_json(run.event.time) : nlohmann::ordered_json();
    // What the step asks and answers, computed from the run (lesson_prompt.h): the question and
    // its choices at the setup, the choice the step marks correct, the ones the run proved.
    const StepPrompt prompt = stepPrompt(step);
    const StepAnswer answer = stepAnswer(step, run, {}, nullptr);
    j["question"] = prompt.question;
    nlohmann::ordered_json choices = nlohmann::ordered_json::array();
    for (std::size_t c = 0; c < prompt.choices.size(); ++c)
        choices.push_back({{"letter", choiceLetter(c)}, {"text", prompt.choices[c]}});
    j["choices"] = std::move(choices);
    j["correct"] =
        prompt.correct >= 0
            ? nlohmann::ordered_json(choiceLetter(static_cast<std::size_t>(prompt.correct)))
            : nlohmann::ordered_json();
    nlohmann::ordered_json proved = nlohmann::ordered_json::array();
    for (const int c : answer.proved) proved.push_back(choiceLetter(static_cast<std::size_t>(c)));
    j["proved"] = std::move(proved);
    j["answer"] = answer.text;
    j["missed"] = answer.missed;
    j["given"] = step.given.size(); // statements of the question checked at the setup
    // The blocks as the setup shows them (t = 0, the question asked), then at the moment.
    const auto blocksJson = [&step](const World& world, bool withSize) {
        nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
        for (std::size_t b = 0; b < world.blocks.size(); ++b) {
            nlohmann::ordered_json block;
            block["name"] = blockLabel(step, b);
            block["position"] = vecJson(world.blocks[b].position);
            block["velocity"] = vecJson(world.blocks[b].velocity);
            if (withSize) block["size"] = vecJson(world.blocks[b].size);
            blocks.push_back(std::move(block));
        }
        return blocks;
    };
    j["setup_blocks"] = blocksJson(stepStartWorld(step), true);
    j["blocks"] = blocksJson(run.world, false);
    j["failures"] = failures;
    return j;
}

} // namespace

int lessonCommand(const std::string& path, std::ostream& out, std::ostream& err,
                  const LessonContext& lessons, bool json) {
    const LessonResult loaded = loadLessonFile(path, lessons);
    if (!loaded.lesson) {
        err << loaded.error.text() << "\n";
        return kExitBadInput;
    }
    const Lesson& lesson = *loaded.lesson;
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    if (!json)
        out << printable(lesson.name, kPrintablePath) << ": " << lesson.steps.size() << " steps\n";
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        const StepRun run = runStepToPause(step);
        const std::vector<std::string> f = checkStep(step, run);
        failures.insert(failures.end(), f.begin(), f.end());
        if (json) {
            steps.push_back(stepJson(i + 1, step, run, f));
            continue;
        }
        out << i + 1 << ". " << printable(step.title, kPrintablePath) << ": "
            << (run.reached ? "paused" : "NOT PAUSED") << " at t = " << run.world.time
            << " s (frame " << run.progress.frames << "), " << run.progress.collisions
            << " collisions, " << run.progress.contacts << " contacts, "
            << methodName(run.world.settings.method) << "\n";
        // The question, its choices (the correct one marked, the ones the run proved) and the
        // answer, computed from the run (lesson_prompt.h).
        const StepPrompt prompt = stepPrompt(step);
        const StepAnswer answer = stepAnswer(step, run, {}, nullptr);
        if (!prompt.question.empty()) {
            out << "     Predict: " << oneLine(prompt.question) << "\n";
            for (std::size_t c = 0; c < prompt.choices.size(); ++c) {
                const bool proved = std::find(answer.proved.begin(), answer.proved.end(),
                                              static_cast<int>(c)) != answer.proved.end();
                out << "       " << choiceLetter(c) << ". " << oneLine(prompt.choices[c])
                    << (static_cast<int>(c) == prompt.correct ? "  (correct)" : "")
                    << (proved ? "  (proved)" : "") << "\n";
            }
        }
        if (!answer.missed.empty())
            out << "     No answer: " << oneLine(answer.missed) << "\n";
        else if (!answer.text.empty())
            out << "     Answer: " << oneLine(answer.text) << "\n";
        for (std::size_t b = 0; b < run.world.blocks.size() && b < 12; ++b) {
            const Block& block = run.world.blocks[b];
            out << "     " << std::left << std::setw(14) << printable(blockLabel(step, b))
                << std::right << " position " << block.position << "  velocity " << block.velocity
                << "\n";
        }
    }
    if (json) {
        nlohmann::ordered_json j;
        j["name"] = lesson.name;
        j["steps"] = std::move(steps);
        // ASCII only: names are \u-escaped, so no byte of them can act on a terminal.
        out << j.dump(-1, ' ', true, nlohmann::ordered_json::error_handler_t::replace) << "\n";
    }
    for (const std::string& f : failures) err << printable(f, kPrintablePath) << "\n";
    return failures.empty() ? kExitOk : kExitBadInput;
}
