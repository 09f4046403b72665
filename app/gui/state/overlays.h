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
//   place    where the window goes at first use (OverlayPlacement, in parentheses)
//   draw     void draw(App&), defined in overlays/ (the ImGui layer; this header only names it);
//            drawnByTheSceneRenderer when the scene renderer draws it (trails, arrows)
// The draw function of a row with a title draws the window's contents (the window is open);
// one without a title draws over the scene.
#pragma once

#include <cstddef>

// Where an overlay window goes at first use: a corner of the scene viewport (anchor 0..1 in x and
// y, e.g. (1, 0) top-right) and its size as a fraction of the viewport, capped in pixels at UI
// scale 1 (scaled by the UI scale).
struct OverlayPlacement {
    float anchorX = 1.0f, anchorY = 0.0f;
    float widthFraction = 0.4f, heightFraction = 0.5f;
    float maxWidth = 480.0f, maxHeight = 480.0f; // px at UI scale 1
};

// clang-format off
#define SANDBOX_OVERLAYS(X)                                                                        \
    X(trails, "trails", "trails (D)", "Trajectories fading with age; C clears them",               \
      false, nullptr, (OverlayPlacement{}), drawnByTheSceneRenderer)                               \
    X(vectors, "vectors", "arrows (V)", "Velocity (thin) and momentum p = m·v (wide) arrows",      \
      true, nullptr, (OverlayPlacement{}), drawnByTheSceneRenderer)                                \
    X(plots, "plots", "plots", "Velocity, momentum and energy against time",                       \
      false, "Plots", (OverlayPlacement{1.0f, 0.0f, 0.42f, 0.52f, 440.0f, 520.0f}),                \
      drawPlotsOverlay)                                                                            \
    X(inspector, "inspector", "inspector", "The last collisions with the lecture's formula filled in", \
      false, "Collision inspector", (OverlayPlacement{1.0f, 1.0f, 0.46f, 0.44f, 460.0f, 330.0f}), \
      drawInspectorOverlay)                                                                        \
    /* The marker with u over the scene, and the momenta window: left, between side by side  */   \
    /* (top) and the timeline (bottom).                                                        */   \
    X(com, "com", "centre of mass", "Centre of mass with its velocity u, and the momenta diagram", \
      false, "Momenta", (OverlayPlacement{0.0f, 0.5f, 0.3f, 0.42f, 300.0f, 300.0f}),              \
      drawComOverlay)                                                                              \
    X(poi, "poi", "impact point", "Point of impact t = a/b of the watched block's last collision", \
      false, nullptr, (OverlayPlacement{}), drawPoiOverlay)                                        \
    /* Leaves room for the plots at the top right. */                                              \
    X(sideBySide, "sidebyside", "3 methods", "The three methods at once: outlines and statistics", \
      false, "Methods side by side", (OverlayPlacement{0.0f, 0.0f, 0.55f, 0.3f, 600.0f, 170.0f}), \
      drawSideBySideOverlay)                                                                       \
    X(timeline, "timeline", "timeline", "Scrub back through the last 60 s and replay",             \
      false, "Timeline", (OverlayPlacement{0.0f, 1.0f, 0.52f, 0.2f, 560.0f, 112.0f}),              \
      drawTimelineOverlay)                                                                         \
    /* Centred, and no bigger than the chart needs: an overlay this size covers much of the    */  \
    /* scene, and every covered pixel is blended again on a software rasteriser.               */  \
    X(cost, "cost", "cost", "Cost per step under each method and the speed-vs-accuracy chart",     \
      false, "Speed versus accuracy", (OverlayPlacement{0.5f, 0.5f, 0.6f, 0.62f, 540.0f, 430.0f}), \
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
    OverlayPlacement place;
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
