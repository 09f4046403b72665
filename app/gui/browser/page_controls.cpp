#include "page_controls.h"

#include "app.h"
#include "input_limits.h"
#include "page_world_controls.h"
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

} // namespace

std::string pageStateJson(const App& app) {
    return pageStateJson(app, spokenScreen(app));
}

std::string pageStateJson(const App& app, const SpokenScreen& s) {
    json screen = {{"scene", s.scene},     {"description", s.description}, {"lesson", s.lesson},
                   {"caption", s.caption}, {"question", s.question},       {"answer", s.answer},
                   {"status", s.status}};
    json scenes = json::array();
    for (const SceneEntry& e : app.shipped.scenes) scenes.push_back({e.path, e.title});
    // [index, name] of the first kListedBlocks blocks and of the selected one (a page of 200,000
    // options, made again every quarter second, would take the page's frames); blockCount says
    // how many there are.
    json blocks = json::array();
    const int count = static_cast<int>(app.sim.world().blocks.size());
    for (int i = 0; i < count; ++i) {
        if (i < static_cast<int>(kListedBlocks) || i == app.sim.selected)
            blocks.push_back({i, app.sim.blockDisplayName(i)});
    }
    const int m = massBlock(app);
    json controls = {
        {"scene", app.sim.scenePath},
        {"scenes", scenes},
        {"lesson", app.lesson.active()},
        {"paused", app.sim.paused},
        {"world", worldControlsJson(app.sim.world().settings)},
        {"undo", app.sim.edits.canUndo()},
        {"redo", app.sim.edits.canRedo()},
        {"block", app.sim.selected},
        {"blocks", blocks},
        {"blockCount", count},
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
    if (applyWorldControl(app, control, value, out.error)) {
        // a world key's control (page_world_controls.h)
    } else if (control == "scene") {
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
            if (acceptTypedNumber(app, "mass", value, b.mass, limits::kMass, mass, out.error)) {
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
