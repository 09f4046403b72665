// Dear ImGui's renderer for this app's OpenGL 3.3 core contexts (the GLFW window and OSMesa),
// in place of ImGui's OpenGL3 backend. It draws the same pixels, split for a software
// rasteriser: the solid triangles (about 90% of the UI's pixels) without sampling the font
// atlas (see ui_draw_runs.h). Call order: Init once the context is current, NewFrame before
// ImGui::NewFrame, Render after ImGui::Render, Shutdown before the context goes.
#pragma once

#include "renderer.h"
#include "ui_frame_base.h"

#include <imgui.h>

#include <memory>
#include <string>
#include <vector>

// A frame's UI as uiRendererRender draws it: ImGui's draw data of the frame (or a copy, when
// ImGui begins the next frame before this one is drawn: app/gui/platform/frame), and the plan
// of the frame's first paint around its windows' backgrounds (desktop GL).
struct UiFrame {
    const ImDrawData* data = nullptr; // ImGui's, or &copy
    ImDrawData copy;
    std::vector<std::unique_ptr<ImDrawList>> lists; // the copy's (kept for their buffers)
    std::vector<ImDrawList*> listPointers;
    // The plan (uiRendererPlanFrameBase): `prepared`, the runs of every command drawn, command
    // k's planRuns[planCmdEnd[k - 1] .. planCmdEnd[k]); `planned`, which opaque fills find their
    // colour already there (in the order of the fills).
    bool prepared = false, planned = false;
    std::vector<UiDrawRun> planRuns, runs; // runs: one command's, while planning
    std::vector<std::size_t> planCmdEnd;
    std::vector<bool> fillSkipped;
    std::vector<UiPaint> paints;
};

bool uiRendererInit(std::string* error);
void uiRendererShutdown();
// Uploads the font atlas if it has none yet (the first frame, or after uiRendererFontsChanged).
void uiRendererNewFrame();
// The font atlas was rebuilt (UI scale): upload it again at the next NewFrame.
void uiRendererFontsChanged();
// After ImGui::Render (no GL call): the frame's UI from ImGui's draw data, copied when `copy`.
void uiRendererCapture(UiFrame& frame, bool copy);
// Whether uiRendererPlanFrameBase plans (desktop GL: on a software rasteriser a fill costs as
// much as any pixel; WebGL: a GPU pays little for one).
bool uiRendererPlansFrameBase();
// No GL call: plans the frame's first paint around the windows' backgrounds in `frame`
// (ui_frame_base.h), for the scene's SceneFrame::base; uiRendererRender then follows the plan.
// The scene's framebuffer size, the pixels it draws in (SceneFrame::drawn) and its arena.
FrameBase uiRendererPlanFrameBase(UiFrame& frame, int sceneWidth, int sceneHeight,
                                  const PixelBox& sceneDrawn, const PixelBox& arena);
// Draws the frame's UI (after the scene).
void uiRendererRender(const UiFrame& frame);
