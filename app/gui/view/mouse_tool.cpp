#include "mouse_tool.h"

#include "app_state.h"
#include "placement.h"

#include <cmath>

namespace {

// Picking tolerance: a few pixels, so thin platforms can be grabbed.
constexpr double kPickTolerancePx = 4.0;

bool validBlock(const App& app, int i) {
    return i >= 0 && i < static_cast<int>(app.world.blocks.size());
}

} // namespace

void mousePress(App& app, MouseButton button, Vec2 screen, bool doubleClick) {
    MouseTool& m = app.mouse;
    const Vec2 world = app.camera.screenToWorld(screen);
    m.cursorWorld = world;
    m.pressWorld = world;
    m.lastScreen = screen;
    const int hit = pickBlock(app.world, world, app.camera.pixelsToMetres(kPickTolerancePx));
    switch (button) {
    case MouseButton::Left:
        if (hit < 0) {
            app.selected = doubleClick ? addBlockAt(app, world) : -1;
            m.mode = MouseTool::Mode::Idle;
            return;
        }
        app.selected = hit;
        m.mode = MouseTool::Mode::Dragging;
        m.block = hit;
        m.startPosition = app.world.blocks[static_cast<std::size_t>(hit)].position;
        m.grabOffset = m.startPosition - world;
        return;
    case MouseButton::Right:
        if (hit < 0 || app.world.blocks[static_cast<std::size_t>(hit)].kind == BodyKind::Static) {
            return;
        }
        app.selected = hit;
        m.mode = MouseTool::Mode::Flinging;
        m.block = hit;
        return;
    case MouseButton::Middle:
        m.mode = MouseTool::Mode::Panning;
        return;
    }
}

void mouseMove(App& app, Vec2 screen) {
    MouseTool& m = app.mouse;
    m.cursorWorld = app.camera.screenToWorld(screen);
    switch (m.mode) {
    case MouseTool::Mode::Dragging:
        if (validBlock(app, m.block)) {
            Block& b = app.world.blocks[static_cast<std::size_t>(m.block)];
            b.position = clampIntoBounds(app.world.bounds, m.cursorWorld + m.grabOffset, b.size);
        }
        break;
    case MouseTool::Mode::Panning:
        app.camera.panPixels(screen - m.lastScreen);
        app.autoFit = false;
        break;
    case MouseTool::Mode::Flinging:
    case MouseTool::Mode::Idle:
        break;
    }
    m.lastScreen = screen;
}

void mouseRelease(App& app, MouseButton button, Vec2 screen) {
    MouseTool& m = app.mouse;
    mouseMove(app, screen);
    if (button == MouseButton::Left && m.mode == MouseTool::Mode::Dragging &&
        validBlock(app, m.block)) {
        Block& b = app.world.blocks[static_cast<std::size_t>(m.block)];
        const auto spot = placeWithoutOverlap(app.world, m.block, b.position, b.size);
        b.position = spot ? *spot : m.startPosition;
        if (b.position != m.startPosition) noteEdit(app, true);
    } else if (button == MouseButton::Right && m.mode == MouseTool::Mode::Flinging &&
               validBlock(app, m.block)) {
        const Vec2 v = m.flingVelocity();
        if (std::isfinite(v.x) && std::isfinite(v.y)) {
            app.world.blocks[static_cast<std::size_t>(m.block)].velocity = v;
            noteEdit(app, true);
        }
    } else if (!(button == MouseButton::Middle && m.mode == MouseTool::Mode::Panning)) {
        return; // a release that ends nothing in progress
    }
    m.mode = MouseTool::Mode::Idle;
    m.block = -1;
}

void mouseWheel(App& app, Vec2 screen, double steps) {
    if (steps == 0.0 || !std::isfinite(steps)) return;
    app.camera.zoomAbout(screen, std::pow(1.15, steps));
    app.autoFit = false;
}

void touchPanZoom(App& app, Vec2 from, Vec2 to, double spreadRatio) {
    if (!std::isfinite(spreadRatio) || spreadRatio <= 0.0) return;
    app.camera.panPixels(to - from);
    app.camera.zoomAbout(to, spreadRatio);
    app.autoFit = false;
}
