#include "lesson_prompt.h"

#include <algorithm>

StepPrompt stepPrompt(const LessonStep& step, const World& setup, const std::vector<int>& blocks,
                      bool asWritten) {
    StepPrompt p;
    p.correct = step.correct;
    const ExprScope scope = setupScope(step, setup, blocks);
    p.caption = renderLessonText(step.captionText, scope, asWritten);
    if (step.question.empty()) return p;
    p.question = renderLessonText(step.questionText, scope, asWritten);
    for (const LessonChoice& c : step.choices)
        p.choices.push_back(renderLessonText(c.text, scope, asWritten));
    return p;
}

StepPrompt stepPrompt(const LessonStep& step) {
    std::vector<int> same(step.scene->blocks.size());
    for (std::size_t i = 0; i < same.size(); ++i) same[i] = static_cast<int>(i);
    return stepPrompt(step, stepStartWorld(step), same, true);
}

std::string choiceLetters(const std::vector<int>& choices) {
    std::string out;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (i > 0) out += i + 1 == choices.size() ? " and " : ", ";
        out += choiceLetter(static_cast<std::size_t>(choices[i]));
    }
    return out;
}

StepAnswer stepAnswer(const LessonStep& step, const StepRun& run,
                      const std::vector<std::string>& changes, const StepRun* asWritten) {
    StepAnswer a;
    a.reached = run.reached;
    if (!run.reached) {
        a.missed = run.missed;
        return a;
    }
    a.proved = provedChoices(step, run);
    if (step.question.empty()) return a;
    const bool changed = !changes.empty();
    std::string text;
    if (changed) {
        text = "With ";
        for (std::size_t i = 0; i < changes.size(); ++i) text += (i > 0 ? ", " : "") + changes[i];
        text += ": ";
    }
    if (!step.choices.empty())
        text += a.proved.empty() ? "none of the choices. " : choiceLetters(a.proved) + ". ";
    // The step's answer explains its correct choice; a run that proves another says that one's.
    const LessonText* said = &step.answerText;
    const bool provesCorrect =
        std::find(a.proved.begin(), a.proved.end(), step.correct) != a.proved.end();
    if (!provesCorrect && !a.proved.empty()) {
        const LessonChoice& first = step.choices[static_cast<std::size_t>(a.proved.front())];
        if (!first.answer.empty()) said = &first.answer;
    }
    text += renderLessonText(*said, eventScope(step, run), !changed);
    if (changed && asWritten && asWritten->reached && step.correct >= 0) {
        const StepPrompt written = stepPrompt(step);
        text += " As written: " + choiceLetter(static_cast<std::size_t>(step.correct)) + ", " +
                written.choices[static_cast<std::size_t>(step.correct)] + ".";
    }
    a.text = text;
    return a;
}
