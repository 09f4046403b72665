#include "link.h"

#include "app_state.h"
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
    if (shippedName(app.sceneFiles, app.scenePath).empty()) return true; // opened, saved
    WorldSettings settings = app.world.settings;
    settings.method = app.scene.settings.method; // the method has a parameter of its own
    return app.blocksEdited || app.world.time > 0.0 || settingsDiffer(app.scene.settings, settings);
}

std::string linkQuery(const App& app) {
    std::string query;
    if (app.lesson.active()) {
        const std::string lesson = shippedName(app.lessonFiles, app.lesson.lesson->path);
        if (!lesson.empty()) {
            add(query, "lesson", lesson);
            add(query, "step", std::to_string(app.lesson.current + 1)); // a step sets the rest
            return query;
        }
    }
    if (!linkCarriesScene(app)) {
        // Named even when it is the default: a bare link opens the last scene of the browser.
        add(query, "scene", shippedName(app.sceneFiles, app.scenePath));
        if (app.world.settings.method != app.scene.settings.method)
            add(query, "method", methodName(app.world.settings.method));
    }
    if (!sameOverlays(app.show, defaultOverlays(app.scene))) add(query, "show", showList(app.show));
    if (app.frame == ViewFrame::CentreOfMass) add(query, "frame", viewFrameName(app.frame));
    return query;
}

std::string linkTooLongMessage(std::size_t chars) {
    return "This scene is too large for a link (" + std::to_string(chars) +
           " characters; browsers take about " + std::to_string(kMaxLinkChars) +
           "): Save (download) it and share the file. The link without it names the rest.";
}
