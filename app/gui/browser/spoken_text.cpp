#include "spoken_text.h"

#include "app.h"
#include "inspector_format.h"
#include "text_format.h"

bool SpokenScreen::operator==(const SpokenScreen& o) const {
    return scene == o.scene && description == o.description && lesson == o.lesson &&
           caption == o.caption && question == o.question && answer == o.answer &&
           status == o.status && error == o.error && changes == o.changes && changed == o.changed;
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
    s.changes = app.sim.changes;
    s.changed = app.sim.lastChange;
    return s;
}

std::vector<std::string> spokenChanges(const SpokenScreen& before, const SpokenScreen& now) {
    std::vector<std::string> said;
    const bool reworded = now.question != before.question && !now.question.empty();
    const bool reanswered = now.answer != before.answer && !now.answer.empty();
    // A change made in the step that changes what it asks or answers: the change, then what
    // reads otherwise now (instead of the step's heading and the answer alone).
    const bool edited = !now.lesson.empty() && now.lesson == before.lesson &&
                        now.changes != before.changes && !now.changed.empty() &&
                        (reworded || reanswered);
    if (edited) {
        std::string line = now.changed;
        if (reworded) line += "; the question now reads: " + now.question;
        if (reanswered) line += "; the answer now reads: " + now.answer;
        said.push_back(line);
    }
    // A step entered (or the same step asked again after R): its heading and its question.
    if (!edited && !now.lesson.empty() &&
        (now.lesson != before.lesson || (now.question != before.question && now.answer.empty()))) {
        std::string line = now.lesson + ".";
        if (!now.question.empty()) line += " " + now.question; // "Predict: ..."
        said.push_back(line);
    }
    if (!edited && reanswered) said.push_back(now.answer); // "Answer: ..." or "No answer: ..."
    if (!now.error.empty() && now.error != before.error) said.push_back("Error: " + now.error);
    return said;
}
