#include "window_glfw.h"

#include "imgui_ext.h"
#include "input_map.h"
#include "ui_renderer_gl.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <cstdio>

// The key map uses GLFW's codes without including GLFW; check they agree.
static_assert(keys::kSpace == GLFW_KEY_SPACE && keys::kMinus == GLFW_KEY_MINUS &&
                  keys::kEqual == GLFW_KEY_EQUAL && keys::kC == GLFW_KEY_C &&
                  keys::kD == GLFW_KEY_D && keys::kF == GLFW_KEY_F && keys::kM == GLFW_KEY_M &&
                  keys::kN == GLFW_KEY_N && keys::kP == GLFW_KEY_P && keys::kQ == GLFW_KEY_Q &&
                  keys::kR == GLFW_KEY_R && keys::kS == GLFW_KEY_S && keys::kV == GLFW_KEY_V &&
                  keys::kEscape == GLFW_KEY_ESCAPE && keys::kTab == GLFW_KEY_TAB &&
                  keys::kDelete == GLFW_KEY_DELETE && keys::kF1 == GLFW_KEY_F1 &&
                  keys::kF11 == GLFW_KEY_F11 && keys::kKeypadSubtract == GLFW_KEY_KP_SUBTRACT &&
                  keys::kKeypadAdd == GLFW_KEY_KP_ADD && keys::k0 == GLFW_KEY_0 &&
                  keys::kEnter == GLFW_KEY_ENTER && keys::kRight == GLFW_KEY_RIGHT &&
                  keys::kLeft == GLFW_KEY_LEFT && keys::kPageUp == GLFW_KEY_PAGE_UP &&
                  keys::kPageDown == GLFW_KEY_PAGE_DOWN && keys::kHome == GLFW_KEY_HOME &&
                  keys::kEnd == GLFW_KEY_END && keys::kKeypad0 == GLFW_KEY_KP_0 &&
                  keys::kKeypadEnter == GLFW_KEY_KP_ENTER &&
                  keys::kLeftControl == GLFW_KEY_LEFT_CONTROL &&
                  keys::kRightControl == GLFW_KEY_RIGHT_CONTROL,
              "input_map.h key codes must match GLFW's");

namespace {

std::string gLastGlfwError;

void onGlfwError(int code, const char* description) {
    gLastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

// Files dropped on the window (a scene, or a trace of the student's engine).
void onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* w = static_cast<WindowGlfw*>(glfwGetWindowUserPointer(window));
    for (int i = 0; w && i < count; ++i) w->droppedFiles.emplace_back(paths[i]);
}

// Installed before ImGui's GLFW backend, which chains to it.
void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    auto* w = static_cast<WindowGlfw*>(glfwGetWindowUserPointer(window));
    if (!w || action != GLFW_PRESS) return;
    w->keyPresses.push_back({key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0});
}

} // namespace

bool windowInit(WindowGlfw& w, int width, int height, const char* title, std::string* error) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        if (error) *error = "cannot start GLFW (" + gLastGlfwError + ")";
        return false;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    // Not forward-compatible: the renderer draws trails and arrow shafts as wide GL lines.
    w.window = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!w.window) {
        if (error) *error = "cannot open an OpenGL 3.3 window (" + gLastGlfwError + ")";
        glfwTerminate();
        return false;
    }
    glfwMakeContextCurrent(w.window);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(w.window, &w);
    glfwSetKeyCallback(w.window, onKey);
    glfwSetDropCallback(w.window, onDrop);
    std::string uiError;
    if (!ImGui_ImplGlfw_InitForOpenGL(w.window, true) || !uiRendererInit(&uiError)) {
        if (error)
            *error = "cannot start the ImGui backends" + (uiError.empty() ? "" : ": " + uiError);
        glfwDestroyWindow(w.window);
        glfwTerminate();
        w.window = nullptr;
        return false;
    }
    w.lastTime = glfwGetTime();
    return true;
}

void windowShutdown(WindowGlfw& w) {
    if (!w.window) return;
    uiRendererShutdown();
    ImGui_ImplGlfw_Shutdown();
    glfwDestroyWindow(w.window);
    glfwTerminate();
    w.window = nullptr;
}

bool windowNewFrame(WindowGlfw& w, double* realSeconds) {
    glfwPollEvents();
    // The close button asks the app, which may ask the user (unsaved edits): not closed here.
    if (glfwWindowShouldClose(w.window)) {
        glfwSetWindowShouldClose(w.window, GLFW_FALSE);
        w.closeRequested = true;
    }
    const double now = glfwGetTime();
    if (realSeconds) *realSeconds = now - w.lastTime;
    w.lastTime = now;
    uiRendererNewFrame();
    ImGui_ImplGlfw_NewFrame();
    imgui_ext::holdKeyTaps(w.keyPresses, w.heldTaps,
                           [&w](int key) { return glfwGetKey(w.window, key) == GLFW_PRESS; });
    return true;
}

void windowPresent(WindowGlfw& w) {
    glfwSwapBuffers(w.window);
}

void windowSetFullscreen(WindowGlfw& w, bool fullscreen) {
    if (fullscreen == w.fullscreen) return;
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (fullscreen && monitor) {
        glfwGetWindowPos(w.window, &w.windowedX, &w.windowedY);
        glfwGetWindowSize(w.window, &w.windowedWidth, &w.windowedHeight);
        const GLFWvidmode* mode = glfwGetVideoMode(monitor);
        if (!mode) return;
        glfwSetWindowMonitor(w.window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
        w.fullscreen = true;
    } else if (!fullscreen) {
        glfwSetWindowMonitor(w.window, nullptr, w.windowedX, w.windowedY, w.windowedWidth,
                             w.windowedHeight, 0);
        w.fullscreen = false;
    }
}

void windowFramebufferSize(const WindowGlfw& w, int* width, int* height) {
    glfwGetFramebufferSize(w.window, width, height);
}

void windowSize(const WindowGlfw& w, int* width, int* height) {
    if (w.fullscreen) {
        *width = w.windowedWidth;
        *height = w.windowedHeight;
        return;
    }
    glfwGetWindowSize(w.window, width, height);
}

void windowRequestClose(WindowGlfw& w) {
    glfwSetWindowShouldClose(w.window, GLFW_TRUE);
}

std::vector<KeyPress> windowTakeKeyPresses(WindowGlfw& w) {
    std::vector<KeyPress> keys;
    keys.swap(w.keyPresses);
    return keys;
}

std::vector<std::string> windowTakeDroppedFiles(WindowGlfw& w) {
    std::vector<std::string> files;
    files.swap(w.droppedFiles);
    return files;
}
