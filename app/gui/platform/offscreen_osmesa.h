// The offscreen backend: an OSMesa OpenGL 3.3 core context (llvmpipe, no display, no GPU) and our
// UI renderer (ui_renderer_gl.h, started and stopped with the context). Init, NewFrame, Finish,
// Shutdown like the window; plus reading the pixels back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

struct OffscreenOsmesa {
    void* context = nullptr;          // OSMesaContext
    std::vector<std::uint8_t> buffer; // BGRA, bottom row first (GL's order)
    int width = 0;
    int height = 0;
};

// Creates the context (ImGui context already created). False with a message on failure.
bool offscreenInit(OffscreenOsmesa& o, int width, int height, std::string* error);
void offscreenShutdown(OffscreenOsmesa& o);
// Starts the backends' frame: display size, a fixed delta time, no mouse.
void offscreenNewFrame(OffscreenOsmesa& o, double deltaSeconds);
// ImGui's part of it alone (no GL call): the input of a frame `width` x `height`.
void offscreenFrameInput(int width, int height, double deltaSeconds);
// Waits for rendering to finish.
void offscreenFinish(OffscreenOsmesa& o);
// The image, top row first, RGBA8 (width * height * 4 bytes).
std::vector<std::uint8_t> offscreenPixelsTopDown(const OffscreenOsmesa& o);
// "4.5 (Core Profile) Mesa ..." and the renderer name, for messages.
std::string offscreenGlDescription();
