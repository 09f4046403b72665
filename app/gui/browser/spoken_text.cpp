#include "spoken_text.h"

#include "app.h"
#include "inspector_format.h"
#include "text_format.h"

bool SpokenScreen::operator==(const SpokenScreen& o) const {
    return scene == o.scene && description == o.description && lesson == o.lesson &&
           caption == o.caption && question == o.question && answer == o.answer &&
           status == o.status && error == o.error;
}

namespace {

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

} // namespace

SpokenScreen spokenScreen(const App& app) {
    SpokenScreen s;
    s.scene = app.sim.scene.name;
    s.description = app.sim.scene.description;
    if (const LessonStep* step = app.lesson.step()) {
        s.lesson = "Lesson: " + app.lesson.lesson->name + ", step " +
                   std::to_string(app.lesson.current + 1) + " of " +
                   std::to_string(app.lesson.lesson->steps.size()) + ": " + step->title;
        const LessonTexts texts = lessonTexts(app.lesson, app.sim);
        s.caption = oneLine(texts.caption);
        if (!texts.question.empty()) {
            s.question = oneLine(texts.question);
            for (const std::string& choice : texts.choices) s.question += " " + choice + ".";
            if (app.lesson.revealed) s.answer = oneLine(texts.answer);
        }
        if (!texts.missed.empty()) s.answer = "No answer: " + texts.missed;
    }
    const long long n = app.sim.run.totals.collisions;
    s.status = std::string(methodName(app.sim.world().settings.method)) +
               " method, t = " + formatNumber(app.sim.world().time) + " s, " +
               (app.sim.paused ? "paused" : "running") + ", " + std::to_string(n) +
               (n == 1 ? " collision" : " collisions");
    s.error = oneLine(app.ui.messages.error);
    return s;
}

std::vector<std::string> spokenChanges(const SpokenScreen& before, const SpokenScreen& now) {
    std::vector<std::string> said;
    // A step entered (or the same step asked again after R): its heading and its question.
    if (!now.lesson.empty() &&
        (now.lesson != before.lesson || (now.question != before.question && now.answer.empty()))) {
        std::string line = now.lesson + ".";
        if (!now.question.empty()) line += " Question: " + now.question;
        said.push_back(line);
    }
    if (!now.answer.empty() && now.answer != before.answer) {
        const bool missed = now.answer.rfind("No answer: ", 0) == 0;
        said.push_back(missed ? now.answer : "Answer: " + now.answer);
    }
    if (!now.error.empty() && now.error != before.error) said.push_back("Error: " + now.error);
    return said;
}
