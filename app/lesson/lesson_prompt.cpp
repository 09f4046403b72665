#include "lesson_prompt.h"

#include "settings_table.h"
#include "text_format.h"

#include <algorithm>

namespace {

std::string number(double v) {
    return formatNumber(v);
}

std::string pair(Vec2 v) {
    return "(" + formatNumber(v.x) + ", " + formatNumber(v.y) + ")";
}

} // namespace

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

std::vector<std::string> setupChanges(const LessonStep& step, const World& now,
                                      const std::vector<int>& blocks, const World& written) {
    std::vector<std::string> said;
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (!row.inScene || settings_table::same(row, written.settings, now.settings)) continue;
        const std::string symbol = row.shown.symbol;
        if (settings_table::isNone(row, now.settings))
            said.push_back("no " + std::string(row.shown.name));
        else
            said.push_back((symbol.empty() ? std::string(row.shown.name) + " " : symbol + " = ") +
                           settings_table::shownValue(row, now.settings, number));
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < step.scene->blocks.size() && i < written.blocks.size(); ++i) {
        const std::string& name = step.scene->blocks[i].name;
        const int at = i < blocks.size() ? blocks[i] : -1;
        if (at < 0 || static_cast<std::size_t>(at) >= now.blocks.size()) {
            said.push_back(name + " deleted");
            continue;
        }
        ++kept;
        const Block& b = now.blocks[static_cast<std::size_t>(at)];
        const Block& w = written.blocks[i];
        if (b.kind != w.kind)
            said.push_back(name + " made " +
                           (b.kind == BodyKind::Static      ? "static"
                            : b.kind == BodyKind::Kinematic ? "kinematic"
                                                            : "dynamic"));
        else if (b.mass != w.mass)
            said.push_back(name + "'s mass " + number(b.mass) + " kg");
        if (b.position.x != w.position.x || b.position.y != w.position.y)
            said.push_back(name + " moved to " + pair(b.position) + " m");
        if (b.velocity.x != w.velocity.x || b.velocity.y != w.velocity.y)
            said.push_back(name + "'s velocity " + pair(b.velocity) + " m/s");
        if (b.size.x != w.size.x || b.size.y != w.size.y)
            said.push_back(name + "'s size " + number(b.size.x) + " x " + number(b.size.y) + " m");
    }
    if (now.blocks.size() > kept) {
        const std::size_t added = now.blocks.size() - kept;
        said.push_back(std::to_string(added) + (added == 1 ? " block" : " blocks") + " added");
    }
    return said;
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
