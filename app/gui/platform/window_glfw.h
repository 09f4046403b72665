// The window backend: a GLFW window with an OpenGL 3.3 core context, ImGui's GLFW backend (input)
// and our UI renderer (ui_renderer_gl.h, started and stopped with the window). Init, NewFrame,
// Present, Shutdown; main_window.cpp owns the loop and draws.
#pragma once

#include "input_map.h"

#include <string>
#include <vector>

struct GLFWwindow;

struct WindowGlfw {
    GLFWwindow* window = nullptr;
    bool fullscreen = false;
    int windowedX = 0, windowedY = 0, windowedWidth = 1280, windowedHeight = 720;
    double lastTime = 0.0;
    std::vector<KeyPress> keyPresses; // since the last windowTakeKeyPresses()
    std::vector<int> heldTaps;        // keys held down one frame for ImGui (imgui_ext::holdKeyTaps)
    std::vector<std::string> droppedFiles; // since the last windowTakeDroppedFiles()
    bool closeRequested = false;           // the close button was pressed (the app decides)
};

// Opens the window (ImGui context already created). False with a message on failure.
bool windowInit(WindowGlfw& w, int width, int height, const char* title, std::string* error);
void windowShutdown(WindowGlfw& w);
// Polls events and starts the backends' frame (the close button sets w.closeRequested). Sets
// `realSeconds` to the time since the previous frame.
bool windowNewFrame(WindowGlfw& w, double* realSeconds);
// Swaps buffers.
void windowPresent(WindowGlfw& w);
void windowSetFullscreen(WindowGlfw& w, bool fullscreen);
void windowFramebufferSize(const WindowGlfw& w, int* width, int* height);
void windowSize(const WindowGlfw& w, int* width, int* height);
void windowRequestClose(WindowGlfw& w);
// The key presses (not repeats) since the last call, in order.
std::vector<KeyPress> windowTakeKeyPresses(WindowGlfw& w);
// The files dropped on the window since the last call (a scene, or a trace: openFile).
std::vector<std::string> windowTakeDroppedFiles(WindowGlfw& w);
