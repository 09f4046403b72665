#include "prepared_frame.h"

#include "app_frame.h"
#include "gl_api.h"

void prepareFrame(const App& app, SceneRenderer& renderer, int framebufferWidth,
                  int framebufferHeight, PreparedFrame& frame, bool copyUi) {
    uiRendererCapture(frame.ui, copyUi);
    const bool plan = uiRendererPlansFrameBase();
    appPrepareScene(app, renderer, framebufferWidth, framebufferHeight, frame.scene, plan);
    if (plan)
        frame.scene.base = uiRendererPlanFrameBase(frame.ui, framebufferWidth, framebufferHeight,
                                                   frame.scene.drawn, frame.scene.arena);
}

void drawFrameScene(SceneRenderer& renderer, const PreparedFrame& frame) {
    glViewport(0, 0, frame.scene.framebufferWidth, frame.scene.framebufferHeight);
    renderer.submit(frame.scene);
}

void drawFrameUi(const PreparedFrame& frame) {
    uiRendererRender(frame.ui);
}

void drawFrame(SceneRenderer& renderer, const PreparedFrame& frame) {
    drawFrameScene(renderer, frame);
    drawFrameUi(frame);
}
