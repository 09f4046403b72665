#include "lesson_questions.h"

#include "lesson_guards.h"
#include "scene_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>

using json = nlohmann::json;
using namespace scene_json;
using namespace lesson_guards;

namespace lesson_questions {

namespace {

// The sides a "reach" event may name.
const char* const kReachSides[] = {"x", "y", "left", "right", "bottom", "top"};

} // namespace

LessonPause parsePause(const json& value, const std::string& path, const Scene& scene) {
    requireObject(value, path);
    checkKeys(value, path,
              {"time", "collision", "first_collision_of", "collision_of", "rest", "reach", "x", "y",
               "left", "right", "bottom", "top", "watch", "within"});
    const char* const events[] = {"time",         "collision", "first_collision_of",
                                  "collision_of", "rest",      "reach"};
    int found = 0;
    for (const char* key : events) found += value.contains(key) ? 1 : 0;
    if (found != 1)
        throw ValueError{path, "must have one of \"time\", \"collision\", \"first_collision_of\", "
                               "\"collision_of\", \"rest\", \"reach\""};
    LessonPause pause;
    if (value.contains("time")) {
        const std::string p = keyPath(path, "time");
        pause.kind = LessonPause::Kind::Time;
        pause.time = number(value["time"], p);
        if (!(pause.time >= 0.0 && pause.time <= kMaxPauseTime))
            throw ValueError{p, "must be from 0 to 600 seconds"};
        for (const char* key : {"watch", "within"})
            if (value.contains(key))
                throw ValueError{keyPath(path, key),
                                 "a time is its own moment: no \"" + std::string(key) + "\""};
        return pause;
    }
    if (value.contains("collision")) {
        const std::string p = keyPath(path, "collision");
        const double k = number(value["collision"], p);
        if (k != std::floor(k) || k < 1 || k > kMaxPauseCollision)
            throw ValueError{p, "must be a whole number from 1 to 1000000"};
        pause.kind = LessonPause::Kind::Collision;
        pause.collision = static_cast<int>(k);
    } else if (value.contains("first_collision_of")) {
        const std::string p = keyPath(path, "first_collision_of");
        pause.kind = LessonPause::Kind::BlockCollision;
        pause.block = requireBlock(scene, value["first_collision_of"], p);
        pause.blockName = value["first_collision_of"].get<std::string>();
    } else if (value.contains("collision_of")) {
        const std::string p = keyPath(path, "collision_of");
        const json& pair = value["collision_of"];
        if (!pair.is_array() || pair.size() != 2)
            throw ValueError{p, "must be the names of two blocks: [\"m1\", \"m2\"]"};
        pause.kind = LessonPause::Kind::PairCollision;
        pause.block = requireBlock(scene, pair[0], indexPath(p, 0));
        pause.other = requireBlock(scene, pair[1], indexPath(p, 1));
        if (pause.block == pause.other) throw ValueError{p, "names one block twice"};
        pause.blockName = pair[0].get<std::string>();
        pause.otherName = pair[1].get<std::string>();
    } else if (value.contains("rest")) {
        const std::string p = keyPath(path, "rest");
        pause.kind = LessonPause::Kind::Rest;
        pause.block = requireBlock(scene, value["rest"], p);
        pause.blockName = value["rest"].get<std::string>();
    } else {
        const std::string p = keyPath(path, "reach");
        pause.kind = LessonPause::Kind::Reach;
        pause.block = requireBlock(scene, value["reach"], p);
        pause.blockName = value["reach"].get<std::string>();
        int sides = 0;
        for (const char* side : kReachSides) {
            if (!value.contains(side)) continue;
            ++sides;
            const std::string sp = keyPath(path, side);
            const json& bound = requireObject(value[side], sp);
            checkKeys(bound, sp, {"min", "max"});
            if (bound.size() != 1)
                throw ValueError{sp, "must be {\"min\": m} (reached from below) or {\"max\": m}"};
            pause.side = side;
            pause.atLeast = bound.contains("min");
            pause.at = number(bound.begin().value(), keyPath(sp, bound.begin().key()));
        }
        if (sides != 1)
            throw ValueError{path, "a \"reach\" needs one place: x, y, left, right, bottom or top, "
                                   "e.g. \"x\": {\"min\": 12}"};
    }
    for (const char* side : kReachSides)
        if (pause.kind != LessonPause::Kind::Reach && value.contains(side))
            throw ValueError{keyPath(path, side), "a place is for \"reach\""};
    pause.watch = kDefaultWatch;
    if (value.contains("watch")) {
        const std::string p = keyPath(path, "watch");
        pause.watch = number(value["watch"], p);
        // 0: the moment is the end of the event's frame itself (an answer about that frame,
        // where the block was put: the live block is where it says).
        if (!(pause.watch == 0.0 || (pause.watch >= kDefaultWatch && pause.watch <= 60.0)))
            throw ValueError{p, "must be 0 (the event's frame) or from 1 to 60 seconds of "
                                "watched motion"};
    }
    if (value.contains("within")) {
        const std::string p = keyPath(path, "within");
        pause.within = number(value["within"], p);
        if (!(*pause.within > 0.0 && *pause.within <= kMaxPauseTime))
            throw ValueError{p, "must be more than 0 and at most 600 seconds"};
    }
    return pause;
}

// A template's lines hold at most kMaxLineChars characters of text of their own (outside {...}):
// what it prints beside its numbers stays within a caption's line, as plain text does.
LessonText templateText(const json& value, const std::string& path, std::size_t maxLines,
                        const Scene& scene, const std::vector<std::string>& valueNames) {
    LessonText t = parseLessonText(text(value, path, maxLines, kMaxTemplateLineChars), scene,
                                   valueNames, path);
    std::size_t line = 0;
    for (const LessonText::Part& part : t.parts) {
        if (part.kind != LessonText::Part::Kind::Literal &&
            part.kind != LessonText::Part::Kind::AsWritten)
            continue;
        for (const char c : part.text) {
            if (c == '\n') {
                line = 0;
            } else if ((static_cast<unsigned char>(c) & 0xc0) != 0x80 && ++line > kMaxLineChars) {
                throw ValueError{path, "has a line longer than " + std::to_string(kMaxLineChars) +
                                           " characters (its text outside {...})"};
            }
        }
    }
    return t;
}

// "values": {"u": "(m1.m*m1.vx0 + m2.m*m2.vx0)/(m1.m + m2.m)"}: named numbers the texts and the
// choices read. A value may read the others, but not itself through them.
void parseValues(const json& value, const std::string& path, const Scene& scene, LessonStep& step) {
    requireObject(value, path);
    if (value.size() > kMaxValues) throw ValueError{path, "more than 20 values"};
    for (const auto& item : value.items()) {
        const std::string& name = item.key();
        bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
        for (const char c : name)
            identifier &= std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        const auto& globals = lessonGlobalNames();
        if (!identifier || std::find(globals.begin(), globals.end(), name) != globals.end() ||
            name == "and" || name == "or" || name == "not" || name == "abs" || name == "sqrt" ||
            name == "min" || name == "max")
            throw ValueError{keyPath(path, name),
                             "a value's name is a word of letters, digits and _ that is not one "
                             "of the world's names (C, g, t, ...)"};
        step.valueNames.push_back(name);
    }
    for (const auto& item : value.items())
        step.values.push_back(parseLessonExpr(string(item.value(), keyPath(path, item.key())),
                                              scene, step.valueNames, false,
                                              keyPath(path, item.key())));
    // No value reads itself, directly or through others (evaluation would never end).
    std::vector<int> state(step.values.size(), 0); // 0 new, 1 on the path, 2 done
    std::function<void(std::size_t)> visit = [&](std::size_t v) {
        if (state[v] == 2) return;
        if (state[v] == 1)
            throw ValueError{keyPath(path, step.valueNames[v]),
                             "reads itself (through other values)"};
        state[v] = 1;
        for (const LessonExpr::Node& n : step.values[v].nodes)
            if (n.kind == LessonExpr::Node::Kind::Value) visit(static_cast<std::size_t>(n.block));
        state[v] = 2;
    };
    for (std::size_t v = 0; v < step.values.size(); ++v) visit(v);
}

// "choices": [{"text": "...", "if": "...", "correct": true}, ...]: 2 to 4, one of them correct.
void parseChoices(const json& value, const std::string& path, const Scene& scene,
                  LessonStep& step) {
    if (!value.is_array()) throw ValueError{path, "must be an array of 2 to 4 choices"};
    if (value.size() < kMinChoices || value.size() > kMaxChoices)
        throw ValueError{path, "must have 2 to 4 choices, not " + std::to_string(value.size())};
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string p = indexPath(path, i);
        const json& c = requireObject(value[i], p);
        checkKeys(c, p, {"text", "if", "correct", "answer"});
        if (!c.contains("text")) throw ValueError{p, "missing \"text\""};
        if (!c.contains("if"))
            throw ValueError{p, "missing \"if\": the condition at the moment that proves it"};
        LessonChoice choice;
        const std::string textPath = keyPath(p, "text");
        choice.text = templateText(c["text"], textPath, 1, scene, step.valueNames);
        if (c.contains("answer")) {
            const std::string ap = keyPath(p, "answer");
            choice.answer = templateText(c["answer"], ap, kMaxCaptionLines, scene, step.valueNames);
        }
        const std::string ifPath = keyPath(p, "if");
        choice.when =
            parseLessonExpr(string(c["if"], ifPath), scene, step.valueNames, true, ifPath);
        if (c.contains("correct")) {
            const std::string cp = keyPath(p, "correct");
            if (!c["correct"].is_boolean()) throw ValueError{cp, "must be true or false"};
            if (c["correct"].get<bool>()) {
                if (step.correct >= 0)
                    throw ValueError{cp, "choice " +
                                             choiceLetter(static_cast<std::size_t>(step.correct)) +
                                             " is already the correct one"};
                step.correct = static_cast<int>(i);
            }
        }
        step.choices.push_back(std::move(choice));
    }
    if (step.correct < 0)
        throw ValueError{path,
                         "no choice is \"correct\": true (the one the step as written proves)"};
}

} // namespace lesson_questions
