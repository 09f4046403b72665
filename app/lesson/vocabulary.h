// The names that lesson files, the command lines and the app share, below all of them: the
// overlay table (what --show, a lesson step's "overlays" and "reveal" and sandbox-cli's lesson
// check name) and the frames of reference (--frame, a lesson step's "frame"). Header-only, so
// sandbox-cli checks lesson files against the app's names without linking the app.
#pragma once

#include <optional>
#include <string>
#include <vector>

// The overlays, in one table: every part of the app that needs the list reads it. --show parses
// its names, the Overlays section of the controls panel shows one checkbox per row (in this
// order), --verbose logs "NAME: on/off", and the frame calls each shown row's draw function (in
// this order; a window row inside its own window, placed by the one placement function).
//
// Adding an overlay: a row here, its file app/gui/overlays/NAME_overlay.cpp defining the draw
// function, and that file in app/gui/CMakeLists.txt (and a line in the README's overlay list).
//
// Columns of X(member, name, label, tooltip, on, title, place, draw):
//   member   its flag in Overlays (app.show.member)
//   name     its --show name (the only column read outside the app: overlayNames() below)
//   label    the checkbox's label (the panel adds the key of the action with the row's name:
//            keyedLabel, input_map.h); tooltip the checkbox's tooltip
//   on       shown by default (before a scene or --show chooses)
//   title    the window's title, or nullptr for what is drawn over the scene only
//   place    where the window docks: its side of the scene and its share (DockWish, in
//            parentheses; sizes in px at UI scale 1): the layout (app/gui/view/dock_layout.h)
//            docks every shown window, the scene takes the rest
//   draw     void draw(App&), defined in app/gui/overlays/ (the ImGui layer; this header only
//            names it); drawnByTheSceneRenderer when the scene renderer draws it (trails, arrows)
// The columns other than `name` are expanded by the app only (app/gui/view/overlays.h), where
// DockWish, kMinPlotShare and the draw functions exist. The draw function of a row with a title
// draws the window's contents (the window is open); one without a title draws over the scene.
// clang-format off
#define SANDBOX_OVERLAYS(X)                                                                        \
    X(trails, "trails", "trails", "Trajectories fading with age; C clears them",                   \
      false, nullptr, (DockWish{}), drawnByTheSceneRenderer)                                       \
    X(vectors, "vectors", "arrows", "Velocity (thin) and momentum p = m·v (wide) arrows",          \
      true, nullptr, (DockWish{}), drawnByTheSceneRenderer)                                        \
    /* Under the panel: the time window and CSV row (115 px at UI scale 1) and three plots of */ \
    /* 14% of the height each (151 px at 1080p), taken from the panel, not from the scene.     */ \
    X(plots, "plots", "plots", "Velocity, momentum and energy against time",                       \
      false, "Plots", (DockWish{DockSide::Panel, 115.0, 3.0, 400.0, 0.42}),                        \
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
    X(contacts, "contacts", "contacts",                                                           \
      "The last frame's contacts: a dot per collision, a ring per resting contact, and friction's " \
      "push along the face (an arrow while sliding, a bar while it holds)",                        \
      false, nullptr, (DockWish{}), drawContactsOverlay)                                          \
    /* A student's trace (docs/compare.md): their blocks as outlines over the reference's. */     \
    X(ghost, "ghost", "your trace", "Your engine's blocks (a trace opened in the Compare section) " \
      "as outlines over the reference's", false, nullptr, (DockWish{}), drawGhostOverlay)         \
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
    /* The chart needs height: the right column, under the inspector, which takes most of the */   \
    /* rest; its rows (240 px at UI scale 1) and the chart: every plot's least share of the    */ \
    /* height (kMinPlotShare, dock_layout.h: 13%, 140 px at 1080p).                             */ \
    X(cost, "cost", "cost", "Cost per step under each method and the speed-vs-accuracy chart",     \
      false, "Speed versus accuracy",                                                              \
      (DockWish{DockSide::Right, 240.0, 0.25, 400.0, kMinPlotShare}), drawCostOverlay)
// clang-format on

// The overlay names, in the table's order (what --show and lesson files may name).
inline std::vector<std::string> overlayNames() {
    std::vector<std::string> names;
#define SANDBOX_OVERLAY_NAME(member, name, label, tooltip, on, title, place, draw)                 \
    names.emplace_back(name);
    SANDBOX_OVERLAYS(SANDBOX_OVERLAY_NAME)
#undef SANDBOX_OVERLAY_NAME
    return names;
}

// The frame of reference the scene is seen in (app/gui/view/view_frame.h): the world's, or the
// centre of mass's.
enum class ViewFrame {
    World,        // the world's frame: what the engine simulates
    CentreOfMass, // moving with the centre of mass of the dynamic blocks
};

// "world" or "com" (the --frame flag's, the URL's and the lesson key's names).
inline const char* viewFrameName(ViewFrame frame) {
    return frame == ViewFrame::CentreOfMass ? "com" : "world";
}
// The frame called `name`; none for an unknown name.
inline std::optional<ViewFrame> parseViewFrame(const std::string& name) {
    if (name == viewFrameName(ViewFrame::World)) return ViewFrame::World;
    if (name == viewFrameName(ViewFrame::CentreOfMass)) return ViewFrame::CentreOfMass;
    return std::nullopt;
}
