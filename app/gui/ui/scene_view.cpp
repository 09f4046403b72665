// The scene's ImGui side: the mouse in the scene (fed to mouse_tool), and what is drawn over the
// GL scene with ImGui's background draw list, in the scene labels' own font: block labels (with
// the current mass), axis numbers, the values of arrows too long to draw to scale
// (arrow_values.cpp), the reference line of a resting stack, the status badge (status_badge.cpp), a
// large collision count where the count is the lesson, the fling readout and the hover tooltip.
#include "app_frame.h"
#include "arrow_values.h"
#include "label_placement.h"
#include "magnifier.h"
#include "number_text.h"
#include "overlay_window.h"

#include "inspector_format.h"
#include "placement.h"
#include "printed_formula.h"
#include "scene_geometry.h"
#include "text_format.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr int kMaxLabelledBlocks = 200;

ImU32 packed(const Color& c) {
    return c.packed();
}

const SceneTheme& theme() {
    return sceneTheme(uiLightTheme());
}

const char* kindText(BodyKind kind) {
    switch (kind) {
    case BodyKind::Dynamic:
        return "dynamic";
    case BodyKind::Static:
        return "static";
    case BodyKind::Kinematic:
        return "kinematic";
    }
    return "";
}

int hoveredBlock(const App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 mouse{io.MousePos.x, io.MousePos.y};
    if (io.WantCaptureMouse || !app.view.camera.viewport().contains(mouse)) return -1;
    return pickBlock(app.sim.world(), app.view.camera.screenToWorld(mouse), 0.0);
}

// `placed`: the rectangles taken on screen, the blocks and each label (the arrows' values
// avoid them).
void drawLabels(const App& app, ImDrawList* dl, Taken& placed) {
    const int n = static_cast<int>(app.sim.world().blocks.size());
    if (n > kMaxLabelledBlocks) return;
    const float lineHeight = ImGui::GetFontSize();
    for (int i = 0; i < n; ++i) {
        const Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
        const bool named = i < static_cast<int>(app.sim.labels.size()) &&
                           !app.sim.labels[static_cast<std::size_t>(i)].name.empty();
        if (!named && n > kCrowdedScene) continue;
        const std::string name = app.sim.blockDisplayName(i);
        char second[48] = "";
        if (b.isDynamic()) {
            // A name that states the mass ("m1 = 1 kg") needs no second line saying it again.
            if (!nameStatesMass(app.sim.labels[static_cast<std::size_t>(i)].name)) {
                std::snprintf(second, sizeof second, "%s kg", formatNumber(b.mass).c_str());
            }
        } else {
            std::snprintf(second, sizeof second, "%s", kindText(b.kind));
        }
        const Vec2 c = app.view.camera.worldToScreen(b.position);
        const double wPx = app.view.camera.metresToPixels(b.size.x);
        const double hPx = app.view.camera.metresToPixels(b.size.y);
        // A block wholly out of the view, or with its middle left or right of it (panned away,
        // or left behind by a step's "moment_camera": the platformer's lift at its edge), is not
        // named: the name would be out of the scene. One partly above or below it (step 2's wall,
        // taller than the view) has its name at the view's edge (below).
        const ScreenRect& vp = app.view.camera.viewport();
        if (c.x < vp.x || c.x > vp.x + vp.width || c.y + hPx * 0.5 < vp.y ||
            c.y - hPx * 0.5 > vp.y + vp.height)
            continue;
        const ImVec2 nameSize = ImGui::CalcTextSize(name.c_str());
        const ImVec2 secondSize = ImGui::CalcTextSize(second);
        const bool twoLines = second[0] && hPx > 2.6 * lineHeight && secondSize.x < wPx - 6.0;
        const float labelW = twoLines ? std::max(nameSize.x, secondSize.x) : nameSize.x;
        const float labelH = (twoLines ? 2.0f : 1.0f) * lineHeight;
        // Its middle, moved into the view where the block runs out of it (the name stays whole
        // in the scene).
        const float mid =
            std::clamp(static_cast<float>(c.x), static_cast<float>(vp.x) + labelW * 0.5f + 2.0f,
                       std::max(static_cast<float>(vp.x) + labelW * 0.5f + 2.0f,
                                static_cast<float>(vp.x + vp.width) - labelW * 0.5f - 2.0f));
        // On the block, centred, or moved up or down in it off the blocks over it (a block
        // sinking into the one under it: lecture3 step 18); else beside it.
        const float top =
            nameSize.x < wPx - 6.0 && hPx > lineHeight + 4.0
                ? clearRowInside(placed, static_cast<std::size_t>(i), mid - labelW * 0.5f,
                                 static_cast<float>(c.y) - labelH * 0.5f, ImVec2(labelW, labelH))
                : NAN;
        const bool inside = std::isfinite(top);
        // White with a dark shadow on the block; the theme's text colour beside it.
        const ImU32 white = IM_COL32(255, 255, 255, 240);
        const ImU32 beside = packed(theme().text);
        if (inside) {
            shadowText(dl, ImVec2(mid - nameSize.x * 0.5f, top), white, name.c_str());
            // On its block (taken already): noted as a text too, which a caption should not hide.
            placed.texts.push_back(
                spanning(mid - labelW * 0.5f, top, mid + labelW * 0.5f, top + labelH));
            if (twoLines) {
                shadowText(dl, ImVec2(mid - secondSize.x * 0.5f, top + lineHeight),
                           IM_COL32(255, 255, 255, 190), second);
            }
        } else if (n <= kCrowdedScene || i == app.sim.selected) {
            // Beside the block; in a crowded scene only for the selected one (a hundred names
            // pushed around each other are noise).
            const float x = mid - nameSize.x * 0.5f;
            // Above or below it, in the view: a block taller than the view (step 2's wall) has
            // its name at the view's top or bottom edge rather than outside the scene.
            const float viewTop = static_cast<float>(vp.y) + 2.0f;
            const float viewBottom =
                std::max(viewTop, static_cast<float>(vp.y + vp.height) - lineHeight - 2.0f);
            const float above = std::clamp(static_cast<float>(c.y - hPx * 0.5) - lineHeight - 2.0f,
                                           viewTop, viewBottom);
            const float below =
                std::clamp(static_cast<float>(c.y + hPx * 0.5) + 2.0f, viewTop, viewBottom);
            const ImVec2 at = freeSpot(placed, vp, x, above, below, nameSize, lineHeight);
            placed.texts.push_back(spanning(at.x, at.y, at.x + nameSize.x, at.y + nameSize.y));
            shadowText(dl, at, beside, name.c_str(), packed(theme().textShadow));
        }
    }
}

// The numbers of the grid along the floor and the left wall; when the camera leaves the floor
// (or the left wall) out of the view, along the view's bottom (or left) edge, so that a position
// a step's question names can be read off the screen.
// Each number taken is added to `placed`, so that the labels drawn after it go around it, and
// to app.ui.axisNumbers: drawn after the overlays (drawYieldedAxisNumbers), each where no caption
// plate covers it (a plate must cover the world somewhere: the numbers yield to it).
void placeAxisNumbers(App& app, Taken& placed) {
    const Camera& cam = app.view.camera;
    const Bounds& bounds = app.sim.world().bounds;
    const ScreenRect& vp = cam.viewport();
    // Every major grid line; a view so close that fewer than two of them are in it along x
    // numbers every grid line (step 25 of lecture3 frames x = 2..8 m: only "5" was written, and
    // its question's x = 3 m and answer's 6.67 m could not be read off).
    const double grid = gridSpacing(cam.pixelsPerMetre(), 12.0);
    const double left = std::max(cam.screenToWorld({vp.x, vp.y}).x, bounds.min.x);
    const double right = std::min(cam.screenToWorld({vp.x + vp.width, vp.y}).x, bounds.max.x);
    const double major = grid * 5.0;
    const double majorsInView = std::floor((right - bounds.min.x) / major + 1e-9) -
                                std::ceil((left - bounds.min.x) / major - 1e-9) + 1.0;
    // (with room between them: 60 px a grid line, as a major line has at least)
    const double step =
        majorsInView < 2.0 && grid * cam.pixelsPerMetre() >= 5.0 * 12.0 ? grid : major;
    const float gap = static_cast<float>(kAxisRowGapPx);
    // Where the floor (the left wall) is below (left of) the view, the numbers go on its edge.
    const Vec2 corner = cam.worldToScreen(bounds.min);
    const bool floorHidden = corner.y > vp.y + vp.height;
    const bool wallHidden = corner.x < vp.x;
    // Under the floor, or as low as the view lets it be (closer to the floor than `gap`).
    const float lowest = static_cast<float>(vp.y + vp.height) - ImGui::GetTextLineHeight();
    const float xRow =
        floorHidden ? lowest - 4.0f : std::min(static_cast<float>(corner.y) + gap, lowest);
    // Only numbers wholly inside the view: a docked window or the caption bar hides what is
    // under it, and nothing drawn for the scene should be there (a number half under the panel).
    const auto inView = [&vp](float x, float y, ImVec2 size) {
        return x >= vp.x && y >= vp.y && x + size.x <= vp.x + vp.width &&
               y + size.y <= vp.y + vp.height;
    };
    // Not under the status badge (taken before them) nor over a number drawn before (the x and
    // the y axis's 0 at the corner, at UI scale 2), nor, on the view's edge, over a block (the
    // platformer's moment leaves the left wall out: "0" fell on the ledge): such a number is left
    // out.
    const std::vector<ScreenRect>& under = placed.texts;
    const auto draw = [&](float x, float y, const char* text) {
        const ImVec2 size = ImGui::CalcTextSize(text);
        const ScreenRect r{x, y, size.x, size.y};
        const auto over = [&r](const ScreenRect& t) { return rectsOverlap(r, t); };
        if (std::any_of(under.begin(), under.end(), over) ||
            std::any_of(placed.blocks.begin(), placed.blocks.end(), over))
            return;
        app.ui.axisNumbers.push_back({r, text});
        placed.texts.push_back(r);
    };
    char text[32];
    float unitX = NAN;      // after the last number drawn on the x axis
    float firstUnitX = NAN; // after the first
    for (double x = bounds.min.x; x <= bounds.max.x + 1e-9; x += step) {
        number_text::printGeneral(text, sizeof text, x, 6); // "%g"
        const Vec2 s = cam.worldToScreen({x, bounds.min.y});
        const ImVec2 size = ImGui::CalcTextSize(text);
        const float at = static_cast<float>(s.x) - size.x * 0.5f;
        if (!inView(at, xRow, size)) continue;
        draw(at, xRow, text);
        unitX = at + size.x + 4.0f;
        if (!std::isfinite(firstUnitX)) firstUnitX = unitX;
    }
    for (double y = bounds.min.y; y <= bounds.max.y + 1e-9; y += step) {
        number_text::printGeneral(text, sizeof text, y, 6); // "%g"
        const Vec2 s = cam.worldToScreen({bounds.min.x, y});
        const ImVec2 size = ImGui::CalcTextSize(text);
        // Left of the wall, closer to it where the margin is narrow (never under the panel).
        const float x = wallHidden ? static_cast<float>(vp.x) + 4.0f
                                   : std::max(static_cast<float>(s.x) - size.x - gap,
                                              static_cast<float>(vp.x) + 2.0f);
        const float ty = static_cast<float>(s.y) - size.y * 0.5f;
        if (inView(x, ty, size)) draw(x, ty, text);
    }
    // The unit, after the last number on the x axis.
    const ImVec2 unitSize = ImGui::CalcTextSize("m");
    // or, where the view ends right after the last (a window beside the world: steps 11, 16, 17
    // and 24 of lecture3 wrote no unit), after the first.
    if (std::isfinite(unitX) && inView(unitX, xRow, unitSize)) {
        draw(unitX, xRow, "m");
    } else if (std::isfinite(firstUnitX) && inView(firstUnitX, xRow, unitSize)) {
        draw(firstUnitX, xRow, "m");
    }
}

// The collision count, large, in the world's top right corner, where the count is the lesson:
// few blocks, no gravity and many collisions (high_mass_ratio's 3141).
void drawLargeCount(const App& app, ImDrawList* dl, Taken& placed) {
    std::size_t dynamic = 0;
    for (const Block& b : app.sim.world().blocks) dynamic += b.isDynamic();
    // (No gravity: the count is the lesson only where nothing rests.)
    if (dynamic == 0 || dynamic > 3 || app.sim.run.totals.collisions < 100 ||
        app.sim.world().settings.gravity != Vec2{}) {
        return;
    }
    char text[48];
    std::snprintf(text, sizeof text, "%llu",
                  static_cast<unsigned long long>(app.sim.run.totals.collisions));
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize() * 3.0f;
    const ImVec2 ts = font->CalcTextSizeA(size, 1e9f, 0.0f, text);
    const ScreenRect world = worldRectOnScreen(app.view.camera, app.sim.world().bounds);
    const char* unit = "collisions";
    const ImVec2 us = ImGui::CalcTextSize(unit);
    // The count over its unit, as one text: there, or moved off the blocks and the texts.
    const ImVec2 both(std::max(ts.x, us.x), ts.y + us.y);
    const ScreenRect& vp = app.view.camera.viewport();
    const float right =
        std::min(static_cast<float>(world.x + world.width), static_cast<float>(vp.x + vp.width)) -
        12.0f * app.view.uiScale;
    const float top =
        std::max(static_cast<float>(world.y), static_cast<float>(vp.y)) + 8.0f * app.view.uiScale;
    const ImVec2 spot = freeSpot(placed, vp, right - both.x, top, top, both, ImGui::GetFontSize());
    placed.texts.push_back({spot.x, spot.y, both.x, both.y});
    const ImVec2 at(spot.x + both.x - ts.x, spot.y);
    const ImU32 color = uiLightTheme() ? IM_COL32(30, 40, 60, 230) : IM_COL32(240, 240, 250, 230);
    dl->AddText(font, size, at, color, text);
    dl->AddText(ImVec2(spot.x + both.x - us.x, at.y + ts.y), packed(theme().axis), unit);
}

// A resting stack's expected top as a dashed line: a method that lets it sink shows the gap.
void drawReferenceLine(const App& app, ImDrawList* dl, Taken& placed) {
    const std::optional<double> top = restingStackTop(app.sim.scene);
    if (!top) return;
    const Bounds& bounds = app.sim.world().bounds;
    const Vec2 a = app.view.camera.worldToScreen({bounds.min.x, *top});
    const Vec2 b = app.view.camera.worldToScreen({bounds.max.x, *top});
    const ImU32 color = uiLightTheme() ? IM_COL32(200, 60, 40, 220) : IM_COL32(255, 120, 90, 220);
    const float dash = 10.0f * app.view.uiScale, y = static_cast<float>(a.y);
    for (float x = static_cast<float>(a.x); x < static_cast<float>(b.x); x += 2.0f * dash) {
        dl->AddLine(ImVec2(x, y), ImVec2(std::min(x + dash, static_cast<float>(b.x)), y), color,
                    2.0f * app.view.uiScale);
    }
    // Its label over the line's right end in the view (the axis numbers are on the left), or
    // under it where that is taken; in fewer words where the long one finds no free spot (a
    // magnifier beside a narrow scene: lecture3 step 18 at 1280x800, UI 1.5).
    const ScreenRect& vp = app.view.camera.viewport();
    const float right = std::min(static_cast<float>(b.x), static_cast<float>(vp.x + vp.width));
    const std::string value = formatNumber(*top) + " m";
    const std::string texts[] = {"top of the stack at the start: " + value,
                                 "top at the start: " + value};
    std::string text;
    ImVec2 at, ts;
    double least = INFINITY;
    for (const std::string& t : texts) {
        const ImVec2 size = ImGui::CalcTextSize(t.c_str());
        const ImVec2 spot = freeSpot(placed, vp, right - size.x - 6.0f, y - size.y - 4.0f, y + 4.0f,
                                     size, ImGui::GetFontSize());
        const double covered =
            coveredAt(placed, vp, spot.x, spot.y, size, ImGui::GetFontSize() * 0.5f);
        if (text.empty() || covered < least) {
            least = covered;
            text = t, at = spot, ts = size;
        }
        if (covered == 0.0) break;
    }
    placed.texts.push_back({at.x, at.y, ts.x, ts.y});
    shadowText(dl, at, color, text.c_str(), packed(theme().textShadow));
}

void drawFlingReadout(const App& app, ImDrawList* dl) {
    if (app.mouse.mode != MouseTool::Mode::Flinging) return;
    const Vec2 v = app.mouse.flingVelocity();
    char text[64];
    std::snprintf(text, sizeof text, "v = (%.2f, %.2f) m/s", v.x, v.y);
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    shadowText(dl, ImVec2(mouse.x + 14.0f, mouse.y + 10.0f), IM_COL32(255, 190, 120, 255), text);
}

void drawHoverTooltip(const App& app) {
    if (app.mouse.mode != MouseTool::Mode::Idle) return;
    const int i = hoveredBlock(app);
    if (i < 0) return;
    const Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
    const auto twoDecimals = [](double v) {
        std::string text;
        number_text::appendFixed(text, v, 2); // "%.2f"
        return text;
    };
    const std::string mass = formatNumber(b.mass);
    const std::string vx = twoDecimals(b.velocity.x), vy = twoDecimals(b.velocity.y);
    // m·v from m and v as printed here, so that the line holds with the digits shown (m = 3 kg,
    // v = 1.23 m/s: p = 3.69, not the 3.70 of the unrounded 1.234).
    const auto momentum = [&mass, &twoDecimals](double m, double v, const std::string& vText) {
        const std::string p = productAsPrinted(mass, vText);
        if (p.empty()) return twoDecimals(m * v);
        return (vText[0] == '-' && p != "0" ? "-" : "") + p;
    };
    ImGui::BeginTooltip();
    ImGui::Text("%s (%s)", app.sim.blockDisplayName(i).c_str(), kindText(b.kind));
    if (b.isDynamic()) ImGui::Text("m = %s kg", mass.c_str());
    ImGui::Text("position = (%.2f, %.2f) m", b.position.x, b.position.y);
    ImGui::Text("v = (%s, %s) m/s", vx.c_str(), vy.c_str());
    if (b.isDynamic()) {
        ImGui::Text("p = m·v = (%s, %s) kg·m/s", momentum(b.mass, b.velocity.x, vx).c_str(),
                    momentum(b.mass, b.velocity.y, vy).c_str());
    }
    ImGui::EndTooltip();
}

} // namespace

void handleSceneMouse(App& app) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsMousePosValid()) return;
    const Vec2 mouse{io.MousePos.x, io.MousePos.y};
    const bool inScene = !io.WantCaptureMouse && app.view.camera.viewport().contains(mouse);
    if (app.mouse.mode != MouseTool::Mode::Idle && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        mouseMove(app.mouse, app.sim, app.view, mouse);
    }
    const MouseButton buttons[3] = {MouseButton::Left, MouseButton::Right, MouseButton::Middle};
    for (int b = 0; b < 3; ++b) {
        if (inScene && ImGui::IsMouseClicked(b)) {
            mousePress(app.mouse, app.sim, app.view, buttons[b], mouse,
                       ImGui::IsMouseDoubleClicked(b));
        }
        if (ImGui::IsMouseReleased(b))
            mouseRelease(app.mouse, app.sim, app.view, buttons[b], mouse);
    }
    if (inScene && io.MouseWheel != 0.0f) mouseWheel(app.view, mouse, io.MouseWheel);
}

ImFont* sceneLabelFont(const App& app) {
    return app.lesson.active() || app.view.presentMode ? uiSlideLabelFont() : uiLabelFont();
}

SceneLabelFont::SceneLabelFont(const App& app) {
    ImGui::PushFont(sceneLabelFont(app));
}

SceneLabelFont::~SceneLabelFont() {
    ImGui::PopFont();
}

ImVec2 placeSceneLabel(App& app, ImVec2 at, ImVec2 size) {
    const ImVec2 free = freeSpot(app.ui.takenOnScreen, app.view.camera.viewport(), at.x, at.y, at.y,
                                 size, ImGui::GetFontSize());
    app.ui.takenOnScreen.texts.push_back({free.x, free.y, size.x, size.y});
    return free;
}

ImVec2 placeSceneLabelAtOneOf(App& app, const std::vector<ImVec2>& tries, ImVec2 size) {
    if (tries.empty()) return ImVec2(0.0f, 0.0f);
    const float gap = ImGui::GetFontSize() * 0.5f; // as freeSpot keeps labels apart
    for (const ImVec2& at : tries) {
        if (coveredAt(app.ui.takenOnScreen, app.view.camera.viewport(), at.x, at.y, size, gap) ==
            0.0) {
            app.ui.takenOnScreen.texts.push_back({at.x, at.y, size.x, size.y});
            return at;
        }
    }
    return placeSceneLabel(app, tries.front(), size);
}

void drawSceneDecorations(App& app) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    ImGui::PushFont(sceneLabelFont(app)); // the scene's labels have a size of their own
    Taken& placed = app.ui.takenOnScreen; // blocks and texts on screen
    placed.blocks.clear();
    placed.texts.clear();
    // The badge first: the axis numbers and the labels go around it (a label or a number under
    // it was hidden: lecture3 steps 3, 8 and 23).
    takeBlocks(app, placed);
    const ScreenRect badge = drawStatusBadge(app, dl);
    if (badge.width > 0.0) placed.texts.push_back(badge);
    drawMagnifier(app, dl, placed); // before the numbers and labels: they go around it
    app.ui.axisNumbers.clear();
    app.ui.captionPlates.clear();
    placeAxisNumbers(app, placed);
    drawReferenceLine(app, dl, placed);
    drawLargeCount(app, dl, placed); // before the labels and values: they go around it
    drawLabels(app, dl, placed);
    std::optional<BlockStrips> blocks; // the values' (they take texts only)
    drawArrowValues(app, dl, placed, blocks);
    drawMomentumValues(app, dl, placed, blocks);
    SceneView forces; // what the scene renderer draws the force arrows from
    forces.world = &app.sim.world();
    forces.vectors = app.view.show.vectors;
    forces.thrustBlock = app.sim.pushedBlock(); // the thrust, or the player's push
    forces.thrust = app.sim.pushForce();
    drawForceValues(app, forces, dl, placed, blocks);
    drawFlingReadout(app, dl);
    ImGui::PopFont();
    drawHoverTooltip(app);
}

void drawYieldedAxisNumbers(const App& app) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const SceneLabelFont font(app);
    const std::vector<ScreenRect>& plates = app.ui.captionPlates;
    for (const UiState::AxisNumber& n : app.ui.axisNumbers) {
        if (std::any_of(plates.begin(), plates.end(),
                        [&n](const ScreenRect& p) { return rectsOverlap(n.rect, p); }))
            continue;
        dl->AddText(ImVec2(static_cast<float>(n.rect.x), static_cast<float>(n.rect.y)),
                    packed(theme().axis), n.text.c_str());
    }
}
