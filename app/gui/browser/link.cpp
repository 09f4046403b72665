#include "link.h"

#include "app.h"
#include "save_naming.h"

#include <filesystem>

namespace {

// The shipped file's name without ".json" when `path` is one of `files`; "" otherwise.
std::string shippedName(const std::vector<SceneEntry>& files, const std::string& path) {
    for (const SceneEntry& s : files)
        if (s.path == path) return std::filesystem::path(path).stem().string();
    return "";
}

void add(std::string& query, const std::string& key, const std::string& value) {
    query += (query.empty() ? "" : "&") + key + "=" + value; // names and values need no escaping
}

// What opening a scene plainly shows: the overlays' defaults, arrows for few blocks.
Overlays defaultOverlays(const Scene& scene) {
    Overlays o;
    o.vectors = vectorsByDefault(scene);
    return o;
}

bool sameOverlays(const Overlays& a, const Overlays& b) {
    for (const OverlayInfo& row : kOverlays)
        if (a.*row.flag != b.*row.flag) return false;
    return true;
}

std::string showList(const Overlays& shown) {
    std::string list;
    for (const OverlayInfo& row : kOverlays)
        if (shown.*row.flag) list += (list.empty() ? "" : ",") + std::string(row.name);
    return list; // "" is a valid value here: no overlay at all
}

} // namespace

bool linkCarriesScene(const App& app) {
    // In a shipped lesson: the step's setup as the student changed it (none: the step says all).
    if (app.lesson.active() && !shippedName(app.shipped.lessons, app.lesson.lesson->path).empty())
        return !lessonChanges(app.lesson, app.sim).empty();
    if (shippedName(app.shipped.scenes, app.sim.scenePath).empty()) return true; // opened, saved
    WorldSettings settings = app.sim.world().settings;
    settings.method = app.sim.scene.settings.method; // the method has a parameter of its own
    return app.sim.blocksEdited || app.sim.world().time > 0.0 ||
           settingsDiffer(app.sim.scene.settings, settings);
}

std::string linkQuery(const App& app) {
    std::string query;
    if (app.lesson.active()) {
        const std::string lesson = shippedName(app.shipped.lessons, app.lesson.lesson->path);
        if (!lesson.empty()) {
            add(query, "lesson", lesson);
            add(query, "step", std::to_string(app.lesson.current + 1)); // a step sets the rest
            return query;
        }
    }
    if (!linkCarriesScene(app)) {
        // Named even when it is the default: a bare link opens the last scene of the browser.
        add(query, "scene", shippedName(app.shipped.scenes, app.sim.scenePath));
        if (app.sim.world().settings.method != app.sim.scene.settings.method)
            add(query, "method", methodName(app.sim.world().settings.method));
    }
    if (!sameOverlays(app.view.show, defaultOverlays(app.sim.scene)))
        add(query, "show", showList(app.view.show));
    if (app.view.frame == ViewFrame::CentreOfMass)
        add(query, "frame", viewFrameName(app.view.frame));
    return query;
}

Scene linkedScene(const App& app) {
    if (app.lesson.active()) return app.sim.sceneOf(lessonSetupWorld(app.lesson, app.sim));
    return app.sim.currentScene();
}

std::string linkTooLongMessage(std::size_t chars) {
    return "This scene is too large for a link (" + std::to_string(chars) +
           " characters; browsers take about " + std::to_string(kMaxLinkChars) +
           "): Save (download) it and share the file. The link without it names the rest.";
}

bool linkSceneTooLarge(const App& app) {
    return linkCarriesScene(app) && app.sim.world().blocks.size() > kMaxLinkBlocks;
}

std::string linkTooManyBlocksMessage(std::size_t blocks) {
    return "This scene is too large for a link (" + std::to_string(blocks) +
           " blocks; a link carries at most " + std::to_string(kMaxLinkBlocks) +
           "): Save (download) it and share the file. The link without it names the rest.";
}
