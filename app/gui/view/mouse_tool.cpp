#include "mouse_tool.h"

#include "placement.h"
#include "simulation_session.h"
#include "view.h"

#include <cmath>

namespace {

// Picking tolerance: a few pixels, so thin platforms can be grabbed.
constexpr double kPickTolerancePx = 4.0;

bool validBlock(const World& world, int i) {
    return i >= 0 && i < static_cast<int>(world.blocks.size());
}

} // namespace

int blockAtScreen(const World& world, const View& view, Vec2 screen) {
    return pickBlock(world, view.camera.screenToWorld(screen),
                     view.camera.pixelsToMetres(kPickTolerancePx));
}

void mousePress(MouseTool& m, SimulationSession& sim, const View& view, MouseButton button,
                Vec2 screen, bool doubleClick) {
    World& w = sim.world();
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
    World& w = sim.world();
    m.cursorWorld = view.camera.screenToWorld(screen);
    switch (m.mode) {
    case MouseTool::Mode::Dragging:
        if (validBlock(w, m.block)) {
            Block& b = w.blocks[static_cast<std::size_t>(m.block)];
            b.position = clampIntoBounds(w.bounds, m.cursorWorld + m.grabOffset, b.size);
        }
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
    World& w = sim.world();
    mouseMove(m, sim, view, screen);
    if (button == MouseButton::Left && m.mode == MouseTool::Mode::Dragging &&
        validBlock(w, m.block)) {
        Block& b = w.blocks[static_cast<std::size_t>(m.block)];
        const auto spot = placeWithoutOverlap(w, m.block, b.position, b.size);
        b.position = spot ? *spot : m.startPosition;
        if (b.position != m.startPosition) sim.noteEdit(true);
    } else if (button == MouseButton::Right && m.mode == MouseTool::Mode::Flinging &&
               validBlock(w, m.block)) {
        const Vec2 v = m.flingVelocity();
        if (std::isfinite(v.x) && std::isfinite(v.y)) {
            w.blocks[static_cast<std::size_t>(m.block)].velocity = v;
            sim.noteEdit(true);
        }
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
