#include "mouse_tool.h"

#include "placement.h"
#include "simulation_session.h"
#include "view.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace {

// Picking tolerance: a few pixels, so thin platforms can be grabbed.
constexpr double kPickTolerancePx = 4.0;

bool validBlock(const World& world, int i) {
    return i >= 0 && i < static_cast<int>(world.blocks.size());
}

// Block i moved (an edit, part of the drag's gesture) to the free spot nearest `desired` inside
// the bounds; it stays where it is when there is none nearby.
void moveTo(SimulationSession& sim, int i, Vec2 desired) {
    const World& w = sim.world();
    const Block& b = w.blocks[static_cast<std::size_t>(i)];
    const auto spot = placeWithoutOverlap(w, i, desired, b.size);
    if (spot && *spot != b.position)
        sim.apply(Edit::setBlock({i, ""}, "position", {spot->x, spot->y}), true);
}

} // namespace

int blockAtScreen(const World& world, const View& view, Vec2 screen) {
    return pickBlock(world, view.camera.screenToWorld(screen),
                     view.camera.pixelsToMetres(kPickTolerancePx));
}

void mousePress(MouseTool& m, SimulationSession& sim, const View& view, MouseButton button,
                Vec2 screen, bool doubleClick) {
    const World& w = sim.world();
    const Vec2 world = view.camera.screenToWorld(screen);
    m.cursorWorld = world;
    m.pressWorld = world;
    m.lastScreen = screen;
    const int hit = blockAtScreen(w, view, screen);
    switch (button) {
    case MouseButton::Left:
        if (hit < 0) {
            sim.selected = doubleClick ? sim.addBlockAt(world) : -1;
            m.mode = MouseTool::Mode::Idle;
            return;
        }
        sim.selected = hit;
        sim.beginGesture(); // the whole drag is one edit: one undo takes it back
        m.mode = MouseTool::Mode::Dragging;
        m.block = hit;
        m.startPosition = w.blocks[static_cast<std::size_t>(hit)].position;
        m.grabOffset = m.startPosition - world;
        return;
    case MouseButton::Right:
        if (hit < 0 || w.blocks[static_cast<std::size_t>(hit)].kind == BodyKind::Static) return;
        sim.selected = hit;
        m.mode = MouseTool::Mode::Flinging;
        m.block = hit;
        return;
    case MouseButton::Middle:
        m.mode = MouseTool::Mode::Panning;
        return;
    }
}

void mouseMove(MouseTool& m, SimulationSession& sim, View& view, Vec2 screen) {
    const World& w = sim.world();
    m.cursorWorld = view.camera.screenToWorld(screen);
    switch (m.mode) {
    case MouseTool::Mode::Dragging:
        // The block follows the cursor to the nearest free spot (never on top of another).
        if (validBlock(w, m.block)) moveTo(sim, m.block, m.cursorWorld + m.grabOffset);
        break;
    case MouseTool::Mode::Panning:
        view.camera.panPixels(screen - m.lastScreen);
        view.autoFit = false;
        break;
    case MouseTool::Mode::Flinging:
    case MouseTool::Mode::Idle:
        break;
    }
    m.lastScreen = screen;
}

void mouseRelease(MouseTool& m, SimulationSession& sim, View& view, MouseButton button,
                  Vec2 screen) {
    const World& w = sim.world();
    mouseMove(m, sim, view, screen);
    if (button == MouseButton::Left && m.mode == MouseTool::Mode::Dragging) {
        // Dropped: the last move (above) left it on a free spot.
    } else if (button == MouseButton::Right && m.mode == MouseTool::Mode::Flinging &&
               validBlock(w, m.block)) {
        const Vec2 v = m.flingVelocity();
        if (std::isfinite(v.x) && std::isfinite(v.y))
            sim.apply(Edit::setBlock({m.block, ""}, "velocity", {v.x, v.y}));
    } else if (!(button == MouseButton::Middle && m.mode == MouseTool::Mode::Panning)) {
        return; // a release that ends nothing in progress
    }
    m.mode = MouseTool::Mode::Idle;
    m.block = -1;
}

void mouseWheel(View& view, Vec2 screen, double steps) {
    if (steps == 0.0 || !std::isfinite(steps)) return;
    view.camera.zoomAbout(screen, std::pow(1.15, steps));
    view.autoFit = false;
}

void touchPanZoom(View& view, Vec2 from, Vec2 to, double spreadRatio) {
    if (!std::isfinite(spreadRatio) || spreadRatio <= 0.0) return;
    view.camera.panPixels(to - from);
    view.camera.zoomAbout(to, spreadRatio);
    view.autoFit = false;
}
