#include "app_log.h"

#include "panel_rows.h"
#include "settings_table.h"

#include <cstdio>

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

} // namespace

LoggedState snapshotForLog(const SimulationSession& sim, const View& view,
                           const LessonSession& lesson) {
    const WorldSettings& settings = sim.world().settings;
    LoggedState s;
    s.scene = sim.scenePath;
    s.paused = sim.paused;
    s.slowMotion = sim.slowMotion;
    s.overlays = view.show;
    s.uiVisible = view.uiVisible;
    s.settings = settings;
    s.thrust = sim.thrust.on;
    const Vec2 pushing = sim.thrustForce();
    s.thrustX = pushing.x;
    s.thrustY = pushing.y;
    s.timeScale = sim.timeScale;
    s.uiScale = view.uiScale;
    s.blocks = static_cast<int>(sim.world().blocks.size());
    s.selected = sim.selected;
    s.trailLength = sim.run.trails.length();
    if (lesson.active()) s.lesson = lessonHeading(lesson) + (lesson.revealed ? " (answer)" : "");
    return s;
}

std::vector<std::string> describeChanges(const LoggedState& a, const LoggedState& b) {
    std::vector<std::string> out;
    auto onOff = [](bool v) { return v ? std::string("on") : std::string("off"); };
    if (a.scene != b.scene) out.push_back("scene: " + b.scene);
    if (a.lesson != b.lesson && !b.lesson.empty()) out.push_back("lesson step " + b.lesson);
    if (a.paused != b.paused) out.push_back(b.paused ? "paused" : "resumed");
    if (a.slowMotion != b.slowMotion) out.push_back("slow motion: " + onOff(b.slowMotion));
    for (const OverlayInfo& o : kOverlays) {
        const bool was = a.overlays.*o.flag, is = b.overlays.*o.flag;
        if (was != is) out.push_back(std::string(o.name) + ": " + onOff(is));
    }
    if (a.trailLength > 0 && b.trailLength == 0) out.push_back("trails cleared");
    if (a.uiVisible != b.uiVisible) out.push_back("ui: " + onOff(b.uiVisible));
    for (const settings_table::WorldKey* row : panelOrder()) {
        if (!settings_table::same(*row, a.settings, b.settings))
            out.push_back(row->key + std::string(": ") +
                          settings_table::logValue(*row, b.settings));
    }
    if (a.thrust != b.thrust) out.push_back("thrust: " + onOff(b.thrust));
    if (a.thrustX != b.thrustX || a.thrustY != b.thrustY) {
        out.push_back(b.thrustX == 0.0 && b.thrustY == 0.0
                          ? std::string("thrust released")
                          : "thrust held: " + number(b.thrustX) + "," + number(b.thrustY) + " N");
    }
    if (a.timeScale != b.timeScale) out.push_back("time scale: " + number(b.timeScale));
    if (a.uiScale != b.uiScale) out.push_back("ui scale: " + number(b.uiScale));
    if (a.blocks != b.blocks) out.push_back("blocks: " + std::to_string(b.blocks));
    if (a.selected != b.selected) out.push_back("selected: " + std::to_string(b.selected));
    return out;
}
