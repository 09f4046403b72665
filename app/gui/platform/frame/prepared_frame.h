// A frame worked out and ready for its GL calls: the scene's (SceneFrame) and the UI's
// (UiFrame). Working it out needs no GL, so that on llvmpipe (software OpenGL, a lecture laptop
// without a GPU) the window's loop and the offscreen benchmark prepare frame N+1 on a second
// thread (frame_worker.h) while the main thread issues frame N's GL calls, when llvmpipe's own
// threads are idle (they rasterise only once the frame is handed over, docs/performance.md).
#pragma once

#include "renderer.h"
#include "ui_renderer_gl.h"

struct App;

struct PreparedFrame {
    SceneFrame scene;
    UiFrame ui;
};

// After ImGui::Render: the scene's frame (appPrepareScene) and the UI's, its first paint planned
// around the windows' backgrounds. `copyUi`: ImGui's draw data copied, for a frame drawn after
// ImGui has begun the next.
void prepareFrame(const App& app, SceneRenderer& renderer, int framebufferWidth,
                  int framebufferHeight, PreparedFrame& frame, bool copyUi);
// Its GL calls: the viewport and the scene (drawFrameScene), then the UI on top (drawFrameUi).
void drawFrame(SceneRenderer& renderer, const PreparedFrame& frame);
void drawFrameScene(SceneRenderer& renderer, const PreparedFrame& frame);
void drawFrameUi(const PreparedFrame& frame);
