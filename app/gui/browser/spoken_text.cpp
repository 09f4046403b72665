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
        // As the caption bar says it (lessonCaption), each line on one line.
        for (const LessonLine& line : lessonCaption(app.lesson, app.sim)) {
            switch (line.kind) {
            case LessonLine::Kind::Caption:
                s.caption = oneLine(line.text);
                break;
            case LessonLine::Kind::Question:
                s.question = oneLine(line.text);
                break;
            case LessonLine::Kind::Choice:
                s.question += " " + oneLine(line.text) + ".";
                break;
            case LessonLine::Kind::Answer:
            case LessonLine::Kind::NoAnswer:
                s.answer = oneLine(line.text);
                break;
            case LessonLine::Kind::Hint:
            case LessonLine::Kind::GoTo:
                break;
            }
        }
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
        if (!now.question.empty()) line += " " + now.question; // "Predict: ..."
        said.push_back(line);
    }
    if (!now.answer.empty() && now.answer != before.answer)
        said.push_back(now.answer); // "Answer: ..." or "No answer: ..."
    if (!now.error.empty() && now.error != before.error) said.push_back("Error: " + now.error);
    return said;
}
