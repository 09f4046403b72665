// Dear ImGui's renderer for this app's OpenGL 3.3 core contexts (the GLFW window and OSMesa),
// in place of ImGui's OpenGL3 backend. It draws the same pixels, split for a software
// rasteriser: the solid triangles (about 90% of the UI's pixels) without sampling the font
// atlas (see ui_draw_runs.h). Call order: Init once the context is current, NewFrame before
// ImGui::NewFrame, Render after ImGui::Render, Shutdown before the context goes.
#pragma once

#include <imgui.h>

#include <string>

class SceneRenderer;

bool uiRendererInit(std::string* error);
void uiRendererShutdown();
// Uploads the font atlas if it has none yet (the first frame, or after uiRendererFontsChanged).
void uiRendererNewFrame();
// The font atlas was rebuilt (UI scale): upload it again at the next NewFrame.
void uiRendererFontsChanged();
void uiRendererRender(const ImDrawData* drawData);
// Desktop GL: has `renderer` plan each frame's first paint around the windows' backgrounds in
// ImGui's draw data of that frame (ui_frame_base.h), which uiRendererRender then follows: call
// ImGui::Render before the scene is drawn, and uiRendererRender after it, every frame.
void uiRendererPlanFrameBase(SceneRenderer& renderer);
