#include "spoken_text.h"

#include "app.h"
#include "inspector_format.h"
#include "text_format.h"

bool SpokenScreen::operator==(const SpokenScreen& o) const {
    return scene == o.scene && description == o.description && lesson == o.lesson &&
           caption == o.caption && question == o.question && answer == o.answer &&
           status == o.status;
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
        for (const LessonLine& line : lessonCaption(app.lesson)) { // as the caption bar says
            if (line.kind == LessonLine::Kind::Caption) s.caption = oneLine(line.text);
            if (line.kind == LessonLine::Kind::Question) s.question = oneLine(line.text);
            if (line.kind == LessonLine::Kind::Answer) s.answer = oneLine(line.text);
        }
    }
    const long long n = app.sim.run.totals.collisions;
    s.status = std::string(methodName(app.sim.world().settings.method)) +
               " method, t = " + formatNumber(app.sim.world().time) + " s, " +
               (app.sim.paused ? "paused" : "running") + ", " + std::to_string(n) +
               (n == 1 ? " collision" : " collisions");
    return s;
}
