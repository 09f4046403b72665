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
        {"undo", app.sim.edits.canUndo()},
        {"redo", app.sim.edits.canRedo()},
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

namespace {

// An edit from the page (the one door); a refusal is the control's error, under the panel's
// field too.
void applyFromPage(App& app, const Edit& edit, const char* field, std::string& error) {
    const EditError refused = app.sim.apply(edit);
    if (refused.empty()) return;
    error = refused.text();
    app.ui.typedWarning.note(field, TypedValue{false, 0.0, error});
}

} // namespace

PageControlOutcome applyPageControl(App& app, const std::string& control,
                                    const std::string& value) {
    PageControlOutcome out;
    const WorldSettings& w = app.sim.world().settings;
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
    } else if (control == "undo") {
        out.action = Action::Undo;
    } else if (control == "redo") {
        out.action = Action::Redo;
    } else if (control == "method") {
        Method method = w.method;
        if (!parseMethod(value.c_str(), method))
            out.error = "method: unknown '" + value + "'";
        else
            applyFromPage(app, Edit::setWorld("method", methodName(method)), "method", out.error);
    } else if (control == "bounciness") {
        double c = w.bounciness;
        if (acceptNumber(app, "bounciness C", value, w.bounciness, limits::kBounciness, c,
                         out.error))
            applyFromPage(app, Edit::setWorld("bounciness", c), "bounciness C", out.error);
    } else if (control == "gravity-x" || control == "gravity-y") {
        Vec2 g = w.gravity;
        double& axis = control == "gravity-x" ? g.x : g.y;
        if (acceptNumber(app, "gravity", value, axis, limits::kGravity, axis, out.error))
            applyFromPage(app, Edit::setWorld("gravity", {g.x, g.y}), "gravity", out.error);
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
            const Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
            double mass = b.mass;
            if (acceptNumber(app, "mass", value, b.mass, limits::kMass, mass, out.error)) {
                const std::string problem = limits::accelerationViolation(length(b.force), mass);
                if (problem.empty()) {
                    applyFromPage(app, Edit::setBlock({i, ""}, "mass", mass), "mass", out.error);
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
