// The overlays, in one table: every part of the app that needs the list reads it. --show parses
// its names, the Overlays section of the controls panel shows one checkbox per row (in this
// order), --verbose logs "NAME: on/off", and the frame calls each shown row's draw function (in
// this order; a window row inside its own window, placed by the one placement function).
//
// Adding an overlay: a row here, its file overlays/NAME_overlay.cpp defining the draw function,
// and that file in app/gui/CMakeLists.txt.
//
// Columns of X(member, name, label, tooltip, on, title, place, draw):
//   member   its flag in Overlays (app.show.member)
//   name     its --show name
//   label    the checkbox's label; tooltip the checkbox's tooltip
//   on       shown by default (before a scene or --show chooses)
//   title    the window's title, or nullptr for what is drawn over the scene only
//   place    where the window docks: its side of the scene and its share (DockWish, in
//            parentheses; sizes in px at UI scale 1): the layout (dock_layout.h) docks every
//            shown window, the scene takes the rest
//   draw     void draw(App&), defined in overlays/ (the ImGui layer; this header only names it);
//            drawnByTheSceneRenderer when the scene renderer draws it (trails, arrows)
// The draw function of a row with a title draws the window's contents (the window is open);
// one without a title draws over the scene.
#pragma once

#include "dock_layout.h"

#include <cstddef>
#include <string>
#include <vector>

// clang-format off
#define SANDBOX_OVERLAYS(X)                                                                        \
    X(trails, "trails", "trails (D)", "Trajectories fading with age; C clears them",               \
      false, nullptr, (DockWish{}), drawnByTheSceneRenderer)                                       \
    X(vectors, "vectors", "arrows (V)", "Velocity (thin) and momentum p = m·v (wide) arrows",      \
      true, nullptr, (DockWish{}), drawnByTheSceneRenderer)                                        \
    X(plots, "plots", "plots", "Velocity, momentum and energy against time",                       \
      false, "Plots", (DockWish{DockSide::Right, 240.0, 3.0, 400.0}),                              \
      drawPlotsOverlay)                                                                            \
    X(inspector, "inspector", "inspector", "The last collisions with the lecture's formula filled in", \
      false, "Collision inspector", (DockWish{DockSide::Right, 200.0, 2.0, 430.0}),                \
      drawInspectorOverlay)                                                                        \
    /* The marker with u over the scene, and the momenta window (square: the bottom strip). */     \
    X(com, "com", "centre of mass", "Centre of mass with its velocity u, and the momenta diagram", \
      false, "Momenta", (DockWish{DockSide::Bottom, 170.0, 1.0, 175.0}),                           \
      drawComOverlay)                                                                              \
    X(poi, "poi", "impact point", "Point of impact t = a/b of the watched block's last collision", \
      false, nullptr, (DockWish{}), drawPoiOverlay)                                                \
    /* A wide table: the bottom strip. */                                                          \
    X(sideBySide, "sidebyside", "3 methods", "The three methods at once: outlines and statistics", \
      false, "Methods side by side", (DockWish{DockSide::Bottom, 420.0, 2.0, 185.0}),              \
      drawSideBySideOverlay)                                                                       \
    X(timeline, "timeline", "timeline", "Scrub back through the last 60 s and replay",             \
      false, "Timeline", (DockWish{DockSide::Bottom, 260.0, 1.0, 110.0}),                          \
      drawTimelineOverlay)                                                                         \
    /* A square picture with its caption beside it: the bottom strip. */                           \
    X(velocitySpace, "velocityspace", "velocity space",                                            \
      "Two blocks' state at (sqrt(m1)·v1, sqrt(m2)·v2): energy a circle, momentum a line, "         \
      "collisions reflections (why high_mass_ratio counts pi)",                                    \
      false, "Velocity space", (DockWish{DockSide::Bottom, 300.0, 1.5, 185.0}),                    \
      drawVelocitySpaceOverlay)                                                                    \
    /* The chart needs height: the right column, under the plots and the inspector. */             \
    X(cost, "cost", "cost", "Cost per step under each method and the speed-vs-accuracy chart",     \
      false, "Speed versus accuracy", (DockWish{DockSide::Right, 200.0, 1.0, 400.0}),              \
      drawCostOverlay)
// clang-format on

// Which overlays are shown: one flag per row.
struct Overlays {
#define SANDBOX_OVERLAY_FLAG(member, name, label, tooltip, on, title, place, draw) bool member = on;
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_FLAG)
#undef SANDBOX_OVERLAY_FLAG
};

// A row of the table, without its draw function (the ImGui layer holds those: ui/overlay_window.h).
struct OverlayInfo {
    bool Overlays::*flag;
    const char* name;
    const char* label;
    const char* tooltip;
    const char* title; // nullptr: drawn over the scene, no window
    DockWish place;
};

// The rows' indices: OverlayId::plots, ...
enum class OverlayId : std::size_t {
#define SANDBOX_OVERLAY_ID(member, name, label, tooltip, on, title, place, draw) member,
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_ID)
#undef SANDBOX_OVERLAY_ID
};

inline constexpr OverlayInfo kOverlays[] = {
#define SANDBOX_OVERLAY_INFO(member, name, label, tooltip, on, title, place, draw)                 \
    {&Overlays::member, name, label, tooltip, title, place},
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_INFO)
#undef SANDBOX_OVERLAY_INFO
};
inline constexpr std::size_t kOverlayCount = sizeof kOverlays / sizeof kOverlays[0];

inline const OverlayInfo& overlayInfo(OverlayId id) {
    return kOverlays[static_cast<std::size_t>(id)];
}

// The overlay names, in the table's order (what --show and lesson files may name). Header-only,
// so sandbox-cli checks lesson files against the table without linking the app.
inline std::vector<std::string> overlayNames() {
    std::vector<std::string> names;
    for (const OverlayInfo& o : kOverlays) names.emplace_back(o.name);
    return names;
}
