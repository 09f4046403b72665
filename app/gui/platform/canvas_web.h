// The browser backend: emscripten's GLFW on a WebGL 2 canvas that fills the page, with ImGui's
// GLFW backend and the project's UI renderer. Init, NewFrame, Shutdown, as ImGui's backends; the
// browser presents the frame itself when the main loop's callback returns. Also the page's
// services the app uses: the URL, local storage, the file picker, downloads and full screen
// (their JavaScript side is in web/index.html).
#pragma once

#include "input_map.h"
#include "touch_input.h"
#include "vec2.h"

#include <string>
#include <vector>

struct GLFWwindow;

// A two-finger gesture since the last frame: the fingers' midpoint moved from `from` to `to`
// (framebuffer pixels) and their distance changed by `spreadRatio`.
struct TouchGesture {
    Vec2 from, to;
    double spreadRatio = 1.0;
};

// A finger's event from the page (touch_input.h), in framebuffer pixels and seconds.
struct TouchEvent {
    TouchPhase phase;
    int id;
    Vec2 pos;
    double time;
};

struct CanvasWeb {
    GLFWwindow* window = nullptr;
    int width = 0, height = 0;       // the canvas, framebuffer pixels (CSS pixels x ratio)
    double devicePixelRatio = 1.0;   // framebuffer pixels per CSS pixel
    bool fullscreen = false;         // the page is full screen
    bool touchScreen = false;        // the device's pointer is coarse (a finger)
    std::vector<TouchEvent> touches; // since the last canvasTakeTouches()
    bool mouseMoved = false;         // a real mouse moved since touch events (if any)
    // Keys pressed since the last frame, and their releases held back (canvas_web.cpp's onKey).
    struct HeldRelease {
        int key, scancode, mods;
    };
    std::vector<int> keysSinceFrame;
    std::vector<HeldRelease> releasesLater, releasesNow;
    double lastTime = 0.0;                // s
    std::vector<KeyPress> keyPresses;     // since the last canvasTakeKeyPresses()
    std::vector<std::string> openedFiles; // dropped or picked, in the browser's file system
    std::vector<TouchGesture> gestures;   // since the last canvasTakeGestures()
};

// Creates the GL context on the page's canvas (ImGui context already created). False with a
// message when the browser has no WebGL 2.
bool canvasInit(CanvasWeb& c, std::string* error);
void canvasShutdown(CanvasWeb& c);
// Follows the page's size and device pixel ratio (the canvas is resized to match), then starts
// the backends' frame. Sets `realSeconds` to the time since the previous frame.
void canvasNewFrame(CanvasWeb& c, double* realSeconds);
std::vector<KeyPress> canvasTakeKeyPresses(CanvasWeb& c);
std::vector<std::string> canvasTakeOpenedFiles(CanvasWeb& c);
std::vector<TouchGesture> canvasTakeGestures(CanvasWeb& c);
std::vector<TouchEvent> canvasTakeTouches(CanvasWeb& c);

// The page's services.
std::string pageQueryString();           // location.search
std::string storageGet(const char* key); // localStorage, "" when unset
void storageSet(const char* key, const std::string& value);
void pageOpenFilePicker();                  // the browser's file dialog
void pageDownload(const std::string& path); // offers a file of the browser's FS
void pageToggleFullscreen();
void pageFirstFrameShown(); // hides the loading note
// The page's text field takes the focus (the on-screen keyboard shows), or gives it back.
void pageSetTyping(bool typing);
// The screen reader's side of the page (page_controls.h): the DOM text and hidden controls from
// pageStateJson(), and one sentence for the polite live region.
void pageShowState(const std::string& json);
void pageAnnounce(const std::string& text);
// What the app is busy with ("Opening big.json (3.9 MB)..."), over the canvas and in a status
// region; "" hides it.
void pageShowProgress(const std::string& text);
// With unsaved edits, the browser asks before the tab is closed or reloaded (beforeunload).
void pageSetUnsavedEdits(bool unsaved);
// The address bar shows this link (link.h: the query, and the scene it carries or ""); the page
// compresses the scene and replaces the history entry (at most every few hundred ms).
void pageSetLink(const std::string& query, const std::string& sceneJson);
// The same link onto the clipboard; the page answers with sandbox_web_link_copied().
void pageCopyLink(const std::string& query, const std::string& sceneJson);
// The scene the opened link carried (#scene=...), decoded by the page into a file before the app
// started: its path, or "". pageLinkError(): why it could not be decoded, or "".
std::string pageLinkScene();
std::string pageLinkError();
