// One frame of the app, shared by the window and the offscreen renderer so both show the same:
// keys and mouse, the fixed-step simulation, the panels, then the scene drawn with GL. The mains
// own the loop and draw ImGui's draw data on top with the platform's UI renderer.
#pragma once

#include "app.h"
#include "input_map.h"

#include <vector>

class SceneRenderer;
struct ImDrawList;
struct SceneFrame;

// Between ImGui::NewFrame() and ImGui::Render(): the key presses since the last frame, the mouse,
// the simulation (when `runClock`: the window passes real time; the offscreen renderer steps
// explicitly) and the UI.
void appFrame(App& app, const std::vector<KeyPress>& keys, double realSeconds, bool runClock);
// After ImGui::Render(): works out the scene's frame (no GL call; SceneRenderer::submit draws it,
// then the UI renderer ImGui's on top). `measureDrawn`: SceneRenderer::prepare's.
void appPrepareScene(const App& app, SceneRenderer& renderer, int framebufferWidth,
                     int framebufferHeight, SceneFrame& frame, bool measureDrawn);
// Does what a key binding says (also used by the panel's buttons).
void applyAction(App& app, Action action);
// Prints the --verbose lines for what changed since the last call.
void logStateChanges(App& app);

// Panels (one file each).
void drawControlsPanel(App& app);
// The class poll's window over the scene (QR code and counts, or the votes at the moment), and
// its section of the controls panel (overlays/class_poll_window.cpp).
void drawPollWindow(App& app);
void pollSection(App& app);
void drawHelpWindow(App& app);
// The quit dialog (unsaved edits) and the Save dialog (a name; overwriting asks), when open.
void drawDialogs(App& app);
// The lesson's caption bar across the top ("n / N · title", caption, question): its height for
// the open step on this screen (app.view.captionHeight, before the frame is laid out; planned
// once a step and screen), then drawn.
void planLessonCaption(App& app);
void drawLessonCaption(App& app);
// The mouse in the scene (mouse_tool.h): select, drag, fling, pan, zoom.
void handleSceneMouse(App& app);
// Over the scene: the axis numbers, the block labels, the arrows' values, the status badge and
// the hover tooltip. Records what they took on screen (the blocks, their labels, the arrows'
// values) in app.ui.takenOnScreen, for the overlays' labels drawn after it (placeSceneLabel).
// The overlays themselves (the table in vocabulary.h) are drawOverlays' (overlay_window.h).
void drawSceneDecorations(App& app);
// The axis numbers drawSceneDecorations placed, drawn after the overlays: those under a caption
// plate over the scene (drawSceneCaption) are left out.
void drawYieldedAxisNumbers(const App& app);
// Its status badge in the scene's top left corner (status_badge.cpp): the method, the time and the
// collisions (in present mode the scene's caption), PAUSED or SLOW MOTION, the frame of reference
// when it is not the world's, and how to start. Returns the rectangle its plates cover (empty
// when nothing is drawn): the scene's labels and axis numbers are placed around it.
ScreenRect drawStatusBadge(const App& app, ImDrawList* dl);
