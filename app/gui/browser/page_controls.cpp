#include "page_controls.h"

#include "app.h"
#include "input_limits.h"
#include "spoken_text.h"

#include <nlohmann/json.hpp>

#include <cstddef>

namespace {

using json = nlohmann::json;

// The selected block when it has a mass to set, else -1.
int massBlock(const App& app) {
    const int i = app.sim.selected;
    if (i < 0 || i >= static_cast<int>(app.sim.world().blocks.size())) return -1;
    return app.sim.world().blocks[static_cast<std::size_t>(i)].isDynamic() ? i : -1;
}

// A typed number checked as the panel checks it (classroom.h): taken into `out`, or refused with
// the panel's warning under `field`.
bool acceptNumber(App& app, const char* field, const std::string& text, double current,
                  const limits::Range& range, double& out, std::string& error) {
    double typed = 0.0;
    if (!limits::parseNumber(text, typed)) {
        error = std::string(field) + ": not a number";
        app.ui.typedWarning.note(field, TypedValue{false, current, error});
        return false;
    }
    const TypedValue check = checkTypedValue(field, typed, current, range);
    if (!app.ui.typedWarning.note(field, check)) {
        error = check.message;
        return false;
    }
    out = check.value;
    return true;
}

} // namespace

std::string pageStateJson(const App& app) {
    const SpokenScreen s = spokenScreen(app);
    json screen = {{"scene", s.scene},     {"description", s.description}, {"lesson", s.lesson},
                   {"caption", s.caption}, {"question", s.question},       {"answer", s.answer},
                   {"status", s.status}};
    json scenes = json::array();
    for (const SceneEntry& e : app.shipped.scenes) scenes.push_back({e.path, e.title});
    json methods = json::array();
    for (int k = 0; k < static_cast<int>(Method::Count); ++k)
        methods.push_back(methodName(static_cast<Method>(k)));
    json blocks = json::array();
    for (int i = 0; i < static_cast<int>(app.sim.world().blocks.size()); ++i)
        blocks.push_back(app.sim.blockDisplayName(i));
    const WorldSettings& w = app.sim.world().settings;
    const int m = massBlock(app);
    json controls = {
        {"scene", app.sim.scenePath},
        {"scenes", scenes},
        {"lesson", app.lesson.active()},
        {"paused", app.sim.paused},
        {"method", methodName(w.method)},
        {"methods", methods},
        {"bounciness", w.bounciness},
        {"gravity-x", w.gravity.x},
        {"gravity-y", w.gravity.y},
        {"block", app.sim.selected},
        {"blocks", blocks},
        {"mass", m >= 0 ? json(app.sim.world().blocks[static_cast<std::size_t>(m)].mass) : json()},
    };
    // Invalid UTF-8 in a scene's text becomes U+FFFD rather than an exception.
    return json{{"screen", screen}, {"controls", controls}}.dump(-1, ' ', false,
                                                                 json::error_handler_t::replace);
}

PageControlOutcome applyPageControl(App& app, const std::string& control,
                                    const std::string& value) {
    PageControlOutcome out;
    WorldSettings& w = app.sim.world().settings;
    if (control == "scene") {
        if (!loadScene(app, value)) out.error = app.ui.messages.error;
    } else if (control == "lesson-previous") {
        out.action = Action::LessonPrevious;
    } else if (control == "lesson-next") {
        out.action = Action::LessonNext;
    } else if (control == "play") {
        out.action = Action::TogglePause;
    } else if (control == "step") {
        out.action = Action::StepOnce;
    } else if (control == "reset") {
        out.action = Action::Reset;
    } else if (control == "method") {
        if (!parseMethod(value.c_str(), w.method)) out.error = "method: unknown '" + value + "'";
    } else if (control == "bounciness") {
        acceptNumber(app, "bounciness C", value, w.bounciness, limits::kBounciness, w.bounciness,
                     out.error);
    } else if (control == "gravity-x" || control == "gravity-y") {
        double& g = control == "gravity-x" ? w.gravity.x : w.gravity.y;
        acceptNumber(app, "gravity", value, g, limits::kGravity, g, out.error);
    } else if (control == "block") {
        double index = -1.0;
        const int n = static_cast<int>(app.sim.world().blocks.size());
        if (!limits::parseNumber(value, index) || index != static_cast<int>(index) || index < -1 ||
            index >= n) {
            out.error = "block: no block '" + value + "'";
        } else {
            app.sim.selected = static_cast<int>(index);
        }
    } else if (control == "mass") {
        const int i = massBlock(app);
        if (i < 0) {
            out.error = "mass: select a dynamic block first";
        } else {
            Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
            double mass = b.mass;
            if (acceptNumber(app, "mass", value, b.mass, limits::kMass, mass, out.error)) {
                const std::string problem = limits::accelerationViolation(length(b.force), mass);
                if (problem.empty()) {
                    b.mass = mass;
                    app.sim.noteEdit(true);
                } else {
                    out.error = "mass: " + problem;
                    app.ui.typedWarning.note("mass", TypedValue{false, b.mass, out.error});
                }
            }
        }
    } else {
        out.error = "no page control '" + control + "'";
    }
    return out;
}
