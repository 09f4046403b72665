#include "canvas_web.h"

#include "app_frame.h"
#include "browser_input.h"
#include "input_map.h"
#include "ui_renderer_gl.h"

#include <emscripten.h>
#include <emscripten/html5.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

CanvasWeb* gCanvas = nullptr; // the one canvas, for the callbacks from the page

// Keys for the app (presses, queued) and for ImGui, which sees only the keys down when a frame
// starts: a key pressed and released between two frames (an on-screen keyboard's Enter, often)
// would be lost, so its release waits until a frame has seen it down.
void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    if (!gCanvas) return;
    CanvasWeb& c = *gCanvas;
    if (action == GLFW_PRESS) {
        c.keyPresses.push_back({key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0});
        c.keysSinceFrame.push_back(key);
    } else if (action == GLFW_RELEASE && std::find(c.keysSinceFrame.begin(), c.keysSinceFrame.end(),
                                                   key) != c.keysSinceFrame.end()) {
        c.releasesLater.push_back({key, scancode, mods});
        return;
    }
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
}

// At a frame's start: the releases held back for the frame before are let through, and those
// held back since wait for this frame.
void releaseHeldKeys(CanvasWeb& c) {
    for (const CanvasWeb::HeldRelease& r : c.releasesNow)
        ImGui_ImplGlfw_KeyCallback(c.window, r.key, r.scancode, GLFW_RELEASE, r.mods);
    c.releasesNow.swap(c.releasesLater);
    c.releasesLater.clear();
    c.keysSinceFrame.clear();
}

void onDrop(GLFWwindow*, int count, const char** paths) {
    if (!gCanvas) return;
    for (int i = 0; i < count; ++i) gCanvas->openedFiles.emplace_back(paths[i]);
}

// JavaScript, not C++: kept as written.
// clang-format off
// The canvas's size in CSS pixels and the device pixel ratio, as the page last measured them
// (web/index.html: on resize, full screen and a change of ratio).
EM_JS(void, page_canvas_size, (double* out), {
    const s = window.sandboxPage.canvasSize;
    HEAPF64[out >> 3] = s.width;
    HEAPF64[(out >> 3) + 1] = s.height;
    HEAPF64[(out >> 3) + 2] = s.ratio;
    HEAPF64[(out >> 3) + 3] = s.fullscreen ? 1 : 0;
    HEAPF64[(out >> 3) + 4] = s.touch ? 1 : 0;
});
// The canvas's backing store, and what emscripten's GLFW reports as the window's and the
// framebuffer's size (both framebuffer pixels here). Not glfwSetWindowSize: it asks for full
// screen when the size equals the screen's, which a page may not do outside a user gesture.
EM_JS(void, canvas_set_backing_size, (int width, int height), {
    Module.canvas.width = width;
    Module.canvas.height = height;
    if (GLFW.active) {
        GLFW.active.width = width;
        GLFW.active.height = height;
    }
});

EM_JS(char*, page_query_string, (), { return allocateUTF8(window.location.search || ""); });
EM_JS(char*, storage_get, (const char* key), {
    try {
        const v = window.localStorage.getItem(UTF8ToString(key));
        return v === null ? 0 : allocateUTF8(v);
    } catch (e) {
        return 0; // storage disabled (private mode, file://): settings are not kept
    }
});
EM_JS(void, storage_set, (const char* key, const char* value), {
    try {
        window.localStorage.setItem(UTF8ToString(key), UTF8ToString(value));
    } catch (e) {
    }
});
EM_JS(void, page_open_file_picker, (), { window.sandboxPage.openFilePicker(); });
EM_JS(void, page_download, (const char* path), { window.sandboxPage.download(UTF8ToString(path)); });
EM_JS(void, page_toggle_fullscreen, (), { window.sandboxPage.toggleFullscreen(); });
EM_JS(void, page_first_frame_shown, (), { window.sandboxPage.firstFrameShown(); });
EM_JS(void, page_set_typing, (int typing), { window.sandboxPage.setTyping(!!typing); });
EM_JS(void, page_show_state, (const char* json), { window.sandboxPage.showState(UTF8ToString(json)); });
EM_JS(void, page_announce, (const char* text), { window.sandboxPage.announce(UTF8ToString(text)); });
EM_JS(void, page_show_progress, (const char* text), { window.sandboxPage.showProgress(UTF8ToString(text)); });
EM_JS(void, page_set_unsaved_edits, (int unsaved), { window.sandboxPage.setUnsavedEdits(!!unsaved); });
EM_JS(void, page_set_link, (const char* query, const char* scene), {
    window.sandboxPage.setLink(UTF8ToString(query), UTF8ToString(scene));
});
EM_JS(void, page_copy_link, (const char* query, const char* scene), {
    window.sandboxPage.copyLink(UTF8ToString(query), UTF8ToString(scene));
});
EM_JS(char*, page_link_scene, (), { return allocateUTF8(window.sandboxPage.linkScene || ""); });
EM_JS(char*, page_link_error, (), { return allocateUTF8(window.sandboxPage.linkError || ""); });
// clang-format on

std::string takeString(char* text) {
    if (!text) return {};
    std::string s = text;
    std::free(text);
    return s;
}

// The canvas follows its CSS size (the page's stylesheet: the whole viewport, in or out of full
// screen): its backing store is that size times the device pixel ratio, at any ratio.
void followPage(CanvasWeb& c) {
    double css[5] = {0.0, 0.0, 1.0, 0.0, 0.0};
    page_canvas_size(css);
    c.fullscreen = css[3] != 0.0;
    c.touchScreen = css[4] != 0.0;
    const double ratio = css[2] > 0.0 && std::isfinite(css[2]) ? css[2] : 1.0;
    const int width = std::max(1, static_cast<int>(std::lround(css[0] * ratio)));
    const int height = std::max(1, static_cast<int>(std::lround(css[1] * ratio)));
    if (width == c.width && height == c.height && ratio == c.devicePixelRatio) return;
    c.width = width;
    c.height = height;
    c.devicePixelRatio = ratio;
    canvas_set_backing_size(width, height);
}

} // namespace

// Called by web/index.html: a file the user picked, already written into the browser's FS.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_file_opened(const char* path) {
    if (gCanvas && path) gCanvas->openedFiles.emplace_back(path);
}

// Called by web/index.html for a wheel event over the canvas (which it keeps from emscripten's
// GLFW: that passes the raw deltas, about 100 per notch and the wrong way round). A touchpad's
// two-finger scroll over the scene pans it, as two fingers do (wheelPans); over the UI, and a
// mouse wheel's notch anywhere, it is ImGui's wheel (a window scrolls, the scene zooms).
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_wheel(double deltaX, double deltaY, int deltaMode,
                                                       int ctrl) {
    if (!gCanvas) return;
    if (wheelPans(deltaX, deltaY, deltaMode, ctrl != 0) && !ImGui::GetIO().WantCaptureMouse) {
        const double r = gCanvas->devicePixelRatio; // the content follows the fingers
        gCanvas->gestures.push_back({{0.0, 0.0}, {-deltaX * r, -deltaY * r}, 1.0});
        return;
    }
    const Vec2 n = wheelNotches(deltaX, deltaY, deltaMode);
    if (n.x != 0.0 || n.y != 0.0) ImGui_ImplGlfw_ScrollCallback(gCanvas->window, n.x, n.y);
}

// Called by web/index.html for each finger that went down, moved or lifted (CSS pixels from the
// canvas's corner, ms on the page's clock).
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_touch(int phase, int id, double x, double y,
                                                       double ms) {
    if (!gCanvas || phase < 0 || phase > 3 || !std::isfinite(x) || !std::isfinite(y)) return;
    const double r = gCanvas->devicePixelRatio;
    gCanvas->touches.push_back({static_cast<TouchPhase>(phase), id, {x * r, y * r}, ms / 1000.0});
}

// Called by web/index.html when a real mouse moves: the pointer is the mouse's again.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_mouse_moved() {
    if (gCanvas) gCanvas->mouseMoved = true;
}

// Called by web/index.html for a two-finger move: midpoints and spread in CSS pixels.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_gesture(double fromX, double fromY, double toX,
                                                         double toY, double spreadRatio) {
    if (!gCanvas || !(spreadRatio > 0.0) || !std::isfinite(spreadRatio)) return;
    const double r = gCanvas->devicePixelRatio;
    gCanvas->gestures.push_back({{fromX * r, fromY * r}, {toX * r, toY * r}, spreadRatio});
}

bool canvasInit(CanvasWeb& c, std::string* error) {
    if (!glfwInit()) {
        if (error) *error = "cannot start GLFW";
        return false;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    c.window = glfwCreateWindow(1280, 720, "Collision sandbox", nullptr, nullptr);
    if (!c.window) {
        if (error) *error = "this browser gives no WebGL 2 context";
        glfwTerminate();
        return false;
    }
    glfwMakeContextCurrent(c.window);
    gCanvas = &c;
    glfwSetDropCallback(c.window, onDrop);
    followPage(c);
    std::string uiError;
    if (!ImGui_ImplGlfw_InitForOpenGL(c.window, true) || !uiRendererInit(&uiError)) {
        if (error) *error = "cannot start the ImGui backends: " + uiError;
        canvasShutdown(c);
        return false;
    }
    glfwSetKeyCallback(c.window, onKey); // instead of ImGui's, which onKey calls
    // Emscripten's GLFW has no cursors (glfwSetCursor does nothing), and ImGui's backend would set
    // the cursor's mode every frame, which there leaves the pointer lock each time.
    ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange;
    // The display's size as the first frame's ImGui_ImplGlfw_NewFrame will set it, so that the
    // fonts main() bakes for the display's height are the first frame's (not baked and uploaded
    // a second time in it).
    int width = 0, height = 0;
    glfwGetWindowSize(c.window, &width, &height);
    ImGui::GetIO().DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    c.lastTime = glfwGetTime();
    return true;
}

void canvasShutdown(CanvasWeb& c) {
    if (!c.window) return;
    uiRendererShutdown();
    ImGui_ImplGlfw_Shutdown();
    glfwDestroyWindow(c.window);
    glfwTerminate();
    c.window = nullptr;
    gCanvas = nullptr;
}

void canvasNewFrame(CanvasWeb& c, double* realSeconds) {
    followPage(c);
    releaseHeldKeys(c);
    const double now = glfwGetTime();
    if (realSeconds) *realSeconds = now - c.lastTime;
    c.lastTime = now;
    uiRendererNewFrame();
    ImGui_ImplGlfw_NewFrame();
}

std::vector<KeyPress> canvasTakeKeyPresses(CanvasWeb& c) {
    std::vector<KeyPress> keys;
    keys.swap(c.keyPresses);
    return keys;
}

std::vector<std::string> canvasTakeOpenedFiles(CanvasWeb& c) {
    std::vector<std::string> files;
    files.swap(c.openedFiles);
    return files;
}

std::vector<TouchGesture> canvasTakeGestures(CanvasWeb& c) {
    std::vector<TouchGesture> gestures;
    gestures.swap(c.gestures);
    return gestures;
}

std::string pageQueryString() {
    return takeString(page_query_string());
}

std::string storageGet(const char* key) {
    return takeString(storage_get(key));
}

void storageSet(const char* key, const std::string& value) {
    storage_set(key, value.c_str());
}

void pageOpenFilePicker() {
    page_open_file_picker();
}

void pageDownload(const std::string& path) {
    page_download(path.c_str());
}

void pageToggleFullscreen() {
    page_toggle_fullscreen();
}

void pageFirstFrameShown() {
    page_first_frame_shown();
}

void pageShowState(const std::string& json) {
    page_show_state(json.c_str());
}

void pageAnnounce(const std::string& text) {
    page_announce(text.c_str());
}

void pageShowProgress(const std::string& text) {
    page_show_progress(text.c_str());
}

void pageSetUnsavedEdits(bool unsaved) {
    page_set_unsaved_edits(unsaved ? 1 : 0);
}

void pageSetLink(const std::string& query, const std::string& sceneJson) {
    page_set_link(query.c_str(), sceneJson.c_str());
}

void pageCopyLink(const std::string& query, const std::string& sceneJson) {
    page_copy_link(query.c_str(), sceneJson.c_str());
}

std::string pageLinkScene() {
    return takeString(page_link_scene());
}

std::string pageLinkError() {
    return takeString(page_link_error());
}

std::vector<TouchEvent> canvasTakeTouches(CanvasWeb& c) {
    std::vector<TouchEvent> touches;
    touches.swap(c.touches);
    return touches;
}

void pageSetTyping(bool typing) {
    page_set_typing(typing ? 1 : 0);
}
