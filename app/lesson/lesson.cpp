// Lesson files: parsing and validation (docs/lesson-format.md). The scene of a step is loaded
// by lesson_scene.cpp (the scene loader, its overrides as edits).
#include "lesson.h"

#include "edit.h"
#include "input_limits.h"
#include "lesson_guards.h"
#include "lesson_input.h"
#include "lesson_questions.h"
#include "lesson_scene.h"
#include "printable.h"
#include "scene_json.h"
#include "settings_table.h"
#include "vocabulary.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <system_error>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace scene_json;
using namespace lesson_guards;
using namespace lesson_questions;
using lesson_scene::SceneCache;

namespace {

// ---- Pause point, camera, expectations ----

Bounds parseCamera(const json& value, const std::string& path) {
    const std::vector<double> b = numbers(value, path, 4);
    if (!(b[0] < b[2] && b[1] < b[3]))
        throw ValueError{path, "must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax"};
    Bounds bounds;
    bounds.min = {b[0], b[1]};
    bounds.max = {b[2], b[3]};
    return bounds;
}

struct QuantityKey {
    const char* key;
    LessonExpect::Quantity quantity;
    bool perBlock;
};
constexpr QuantityKey kQuantities[] = {
    {"x", LessonExpect::Quantity::X, true},
    {"y", LessonExpect::Quantity::Y, true},
    {"vx", LessonExpect::Quantity::Vx, true},
    {"vy", LessonExpect::Quantity::Vy, true},
    {"time", LessonExpect::Quantity::Time, false},
    {"collisions", LessonExpect::Quantity::Collisions, false},
    {"kinetic_energy", LessonExpect::Quantity::KineticEnergy, false},
    {"max_penetration", LessonExpect::Quantity::MaxPenetration, false},
    {"left", LessonExpect::Quantity::Left, true},
    {"right", LessonExpect::Quantity::Right, true},
    {"bottom", LessonExpect::Quantity::Bottom, true},
    {"top", LessonExpect::Quantity::Top, true},
    {"mass", LessonExpect::Quantity::Mass, true},
    {"frame_rate", LessonExpect::Quantity::FrameRate, false},
    {"bounciness", LessonExpect::Quantity::Bounciness, false},
};
// Pairs written as one key: "position": [x, y] and so on.
struct PairKey {
    const char* key;
    LessonExpect::Quantity first, second;
    bool perBlock;
};
constexpr PairKey kPairs[] = {
    {"position", LessonExpect::Quantity::X, LessonExpect::Quantity::Y, true},
    {"velocity", LessonExpect::Quantity::Vx, LessonExpect::Quantity::Vy, true},
    {"momentum", LessonExpect::Quantity::MomentumX, LessonExpect::Quantity::MomentumY, false},
};

// A number (equal within the tolerance) or {"min": a, "max": b}.
void parseTarget(const json& value, const std::string& path, LessonExpect& e) {
    if (value.is_object()) {
        checkKeys(value, path, {"min", "max"});
        if (value.empty()) throw ValueError{path, "needs \"min\" or \"max\""};
        if (value.contains("min")) e.min = number(value["min"], keyPath(path, "min"));
        if (value.contains("max")) e.max = number(value["max"], keyPath(path, "max"));
        if (e.min && e.max && *e.min > *e.max) throw ValueError{path, "min is more than max"};
        return;
    }
    if (!value.is_number()) throw ValueError{path, "must be a number or {\"min\": a, \"max\": b}"};
    e.equals = number(value, path);
}

void parseExpect(const json& value, const std::string& path, const Scene& scene,
                 const std::string& where, std::vector<LessonExpect>& out) {
    requireObject(value, path);
    LessonExpect base;
    base.where = where;
    int block = -1;
    if (value.contains("block"))
        block = requireBlock(scene, value["block"], keyPath(path, "block"));
    if (value.contains("tolerance")) {
        base.tolerance = number(value["tolerance"], keyPath(path, "tolerance"));
        if (!(base.tolerance >= 0.0)) throw ValueError{keyPath(path, "tolerance"), "must be >= 0"};
    }
    std::vector<LessonExpect> found;
    auto add = [&](LessonExpect::Quantity q, bool perBlock, const json& target,
                   const std::string& p) {
        if (target.is_null()) return; // [null, 0]: only the second is checked
        if (perBlock && block < 0) throw ValueError{path, "needs \"block\" for " + p};
        LessonExpect e = base;
        e.quantity = q;
        if (perBlock) {
            e.block = block;
            e.blockName = value["block"].get<std::string>();
        }
        parseTarget(target, p, e);
        found.push_back(e);
    };
    bool perBlockKey = false;
    for (const auto& item : value.items()) {
        const std::string& key = item.key();
        const std::string p = keyPath(path, key);
        if (key == "block" || key == "tolerance") continue;
        bool known = false;
        for (const QuantityKey& q : kQuantities) {
            if (key != q.key) continue;
            known = true;
            perBlockKey |= q.perBlock;
            add(q.quantity, q.perBlock, item.value(), p);
        }
        for (const PairKey& q : kPairs) {
            if (key != q.key) continue;
            known = true;
            perBlockKey |= q.perBlock;
            if (!item.value().is_array() || item.value().size() != 2)
                throw ValueError{p, "must be an array of 2 (numbers, {\"min\", \"max\"} or null)"};
            add(q.first, q.perBlock, item.value()[0], indexPath(p, 0));
            add(q.second, q.perBlock, item.value()[1], indexPath(p, 1));
        }
        if (!known) throw ValueError{p, "unknown key"};
    }
    if (found.empty()) throw ValueError{path, "expects nothing (give e.g. \"vx\" or \"position\")"};
    if (block >= 0 && !perBlockKey)
        throw ValueError{keyPath(path, "block"), "no block quantity (x, y, vx, vy, position, "
                                                 "velocity) to go with it"};
    out.insert(out.end(), found.begin(), found.end());
}

// An array of expectations ("expect" or "given").
void parseExpects(const json& list, const std::string& path, const Scene& scene,
                  const std::string& source, std::vector<LessonExpect>& out) {
    if (!list.is_array()) throw ValueError{path, "must be an array"};
    if (list.size() > kMaxExpects) throw ValueError{path, "more than 100 expectations"};
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string at = indexPath(path, i);
        parseExpect(list[i], at, scene, source + ": " + at, out);
    }
}

LessonStep parseStep(const json& value, const std::string& path, const std::string& source,
                     const LessonContext& context, SceneCache& cache) {
    requireObject(value, path);
    checkKeys(value, path,
              {"title",  "caption",       "scene", "overrides", "overlays", "select",   "thrust",
               "camera", "moment_camera", "frame", "pause_at",  "values",   "question", "choices",
               "answer", "reveal",        "given", "expect",    "input",    "edits"});
    LessonStep step;
    step.place = source + ": " + path;
    if (!value.contains("title")) throw ValueError{path, "missing \"title\""};
    step.title = text(value["title"], keyPath(path, "title"), 1);
    if (!value.contains("caption")) throw ValueError{path, "missing \"caption\""};
    step.caption = // checked as text here, as a template once the scene's names are known
        text(value["caption"], keyPath(path, "caption"), kMaxCaptionLines, kMaxTemplateLineChars);
    lesson_scene::loadStepScene(value, path, context, cache, step);
    const Scene& scene = *step.scene;
    if (value.contains("overlays"))
        step.overlays =
            overlayList(value["overlays"], keyPath(path, "overlays"), context.overlayNames);
    if (value.contains("select"))
        step.selected = requireBlock(scene, value["select"], keyPath(path, "select"));
    if (value.contains("thrust")) {
        const std::string p = keyPath(path, "thrust");
        step.thrust = number(value["thrust"], p, limits::kThrust);
        if (step.selected < 0)
            throw ValueError{p, "needs \"select\": the block the arrow keys push"};
        const BlockDef& b = scene.blocks[static_cast<std::size_t>(step.selected)];
        if (b.kind != BodyKind::Dynamic)
            throw ValueError{p, "the selected block " + quoted(b.name) +
                                    " has no mass: thrust pushes a dynamic block"};
    }
    if (value.contains("input"))
        step.input = parseLessonInput(value["input"], keyPath(path, "input"), scene);
    if (value.contains("edits")) { // applied at their frames (docs/edits.md), named by the file
        step.edits = editLogOf(value["edits"], keyPath(path, "edits"));
        for (LogLine& line : step.edits.lines) line.place = source + ": " + line.place;
    }
    if (value.contains("camera"))
        step.camera = parseCamera(value["camera"], keyPath(path, "camera"));
    if (value.contains("frame")) {
        // The app's frames of reference (vocabulary.h): the world's, or the centre of mass's.
        const std::string p = keyPath(path, "frame");
        const std::string name = string(value["frame"], p);
        const std::optional<ViewFrame> frame = parseViewFrame(name);
        if (!frame)
            throw ValueError{p, "unknown frame " + quoted(name) + " (expected " +
                                    viewFrameName(ViewFrame::World) + " or " +
                                    viewFrameName(ViewFrame::CentreOfMass) + ")"};
        step.frame = *frame;
    }
    if (value.contains("pause_at")) {
        step.pause = parsePause(value["pause_at"], keyPath(path, "pause_at"), scene);
        // A time pause must be reachable within the step's budget; a collision pause is searched
        // for within it (lesson_runner.h), and fails with its place when it does not come.
        if (step.pause.kind == LessonPause::Kind::Time &&
            static_cast<double>(maxStepFrames(step)) < pauseFrames(step))
            throw ValueError{keyPath(keyPath(path, "pause_at"), "time"),
                             dumpValue(step.pause.time) + " s at " +
                                 dumpValue(1.0 / scene.settings.dt) + " frames per second, " +
                                 std::to_string(scene.settings.substeps) + " substeps and " +
                                 std::to_string(scene.blocks.size()) +
                                 " blocks is more than a step may run (1e8 block-steps: blocks x "
                                 "frames x substeps)"};
    }
    if (value.contains("moment_camera")) { // the moment's framing: a step that pauses has one
        const std::string p = keyPath(path, "moment_camera");
        step.momentCamera = parseCamera(value["moment_camera"], p);
        if (step.pause.kind == LessonPause::Kind::None)
            throw ValueError{p, "frames the moment: needs \"pause_at\""};
    }
    if (value.contains("values"))
        parseValues(value["values"], keyPath(path, "values"), scene, step);
    step.captionText = templateText(value["caption"], keyPath(path, "caption"), kMaxCaptionLines,
                                    scene, step.valueNames);
    if (value.contains("question")) {
        const std::string p = keyPath(path, "question");
        step.question = string(value["question"], p);
        step.questionText =
            templateText(value["question"], p, kMaxCaptionLines, scene, step.valueNames);
        if (!value.contains("answer")) throw ValueError{path, "a \"question\" needs an \"answer\""};
        if (!value.contains("choices"))
            throw ValueError{path, "a \"question\" needs \"choices\" (2 to 4 predictions)"};
        parseChoices(value["choices"], keyPath(path, "choices"), scene, step);
    } else if (value.contains("choices")) {
        throw ValueError{keyPath(path, "choices"), "choices answer a \"question\": needs one"};
    }
    if (value.contains("answer")) {
        const std::string p = keyPath(path, "answer");
        if (!value.contains("question")) throw ValueError{p, "an answer needs a \"question\""};
        step.answer = string(value["answer"], p);
        step.answerText =
            templateText(value["answer"], p, kMaxCaptionLines, scene, step.valueNames);
    }
    if (value.contains("reveal")) {
        if (!value.contains("question"))
            throw ValueError{keyPath(path, "reveal"), "reveals with the answer: needs a "
                                                      "\"question\""};
        step.reveal = overlayList(value["reveal"], keyPath(path, "reveal"), context.overlayNames);
    }
    if (value.contains("given")) {
        if (!value.contains("question"))
            throw ValueError{keyPath(path, "given"), "what a question states: needs a "
                                                     "\"question\""};
        parseExpects(value["given"], keyPath(path, "given"), scene, source, step.given);
    }
    if (value.contains("expect"))
        parseExpects(value["expect"], keyPath(path, "expect"), scene, source, step.expect);
    return step;
}

Lesson parseLessonValue(const json& root, const std::string& source, const LessonContext& context) {
    requireObject(root, "(top level)");
    checkKeys(root, "", {"name", "description", "steps"});
    Lesson lesson;
    if (!root.contains("name")) throw ValueError{"(top level)", "missing \"name\""};
    lesson.name = text(root["name"], "name", 1);
    if (root.contains("description"))
        lesson.description = text(root["description"], "description", 20, 2000);
    if (!root.contains("steps")) throw ValueError{"(top level)", "missing \"steps\""};
    const json& steps = root["steps"];
    if (!steps.is_array()) throw ValueError{"steps", "must be an array"};
    if (steps.empty()) throw ValueError{"steps", "must have at least one step"};
    if (steps.size() > kMaxSteps) throw ValueError{"steps", "more than 1000 steps"};
    SceneCache cache;
    cache.maxBlocks = context.maxBlocks;
    for (std::size_t i = 0; i < steps.size(); ++i)
        lesson.steps.push_back(parseStep(steps[i], indexPath("steps", i), source, context, cache));
    return lesson;
}

// Printable and bounded, as the scene loader's errors (scene_error.h), whatever the file's name.
LessonResult lessonFailure(const std::string& where, const std::string& message) {
    LessonResult r;
    r.error = ::sceneError(where, message);
    return r;
}

} // namespace

const char* quantityName(LessonExpect::Quantity q) {
    for (const QuantityKey& k : kQuantities)
        if (k.quantity == q) return k.key;
    switch (q) {
    case LessonExpect::Quantity::MomentumX:
        return "momentum x";
    case LessonExpect::Quantity::MomentumY:
        return "momentum y";
    default:
        return "?";
    }
}

LessonResult parseLesson(const std::string& text, const std::string& sourceName,
                         const LessonContext& context) {
    json root;
    if (auto error = parseJsonText(text, sourceName, root))
        return lessonFailure(error->where, error->message);
    try {
        LessonResult r;
        r.lesson = parseLessonValue(root, sourceName, context);
        return r;
    } catch (const ValueError& e) {
        return lessonFailure(sourceName + ": " + e.path, e.message);
    }
}

LessonResult loadLessonFile(const std::string& path, LessonContext context) {
    std::string text;
    if (auto error = readJsonFile(path, text)) return lessonFailure(error->where, error->message);
    if (context.baseDir.empty()) context.baseDir = fs::path(path).parent_path().string();
    context.lessonFile = path;
    LessonResult r = parseLesson(text, path, context);
    if (r.lesson) r.lesson->path = path;
    return r;
}

std::optional<std::size_t> stepIndex(const Lesson& lesson, long long number, std::string* error) {
    const long long count = static_cast<long long>(lesson.steps.size());
    if (number >= 1 && number <= count) return static_cast<std::size_t>(number - 1);
    if (error) {
        *error = printable(lesson.path.empty() ? lesson.name : lesson.path, kPrintablePath) +
                 ": no step " + std::to_string(number) + " (the lesson has steps 1 to " +
                 std::to_string(count) + ")";
    }
    return std::nullopt;
}

double pauseFrames(const LessonStep& step) {
    const double dt = step.scene->settings.dt;
    const double seconds = step.pause.kind == LessonPause::Kind::Time
                               ? step.pause.time
                               : step.pause.within.value_or(kCollisionSearchSeconds) +
                                     step.pause.watch * step.timeScale;
    return std::ceil(seconds / dt) + 2;
}

int maxStepFrames(const LessonStep& step) {
    const Scene& scene = *step.scene;
    const double dt = scene.settings.dt;
    // A time pause: the frames to T and a margin (frame times are sums of dt).
    const double wanted = step.pause.kind == LessonPause::Kind::Time
                              ? std::ceil((step.pause.time * 1.01 + 1.0) / dt) + 2
                              : pauseFrames(step);
    const double perFrame = static_cast<double>(std::max<std::size_t>(1, scene.blocks.size())) *
                            std::max(1, scene.settings.substeps);
    const double budget = std::floor(kMaxStepBlockSteps / perFrame);
    return static_cast<int>(std::max(1.0, std::min(wanted, budget)));
}

bool isLessonText(const std::string& text) {
    return jsonRootHasKey(text, "steps"); // a scene is not parsed twice to be told apart
}

bool isLessonFile(const std::string& path) {
    std::string text;
    if (readJsonFile(path, text)) return false;
    return isLessonText(text);
}
