// sandbox in a browser: the same app as the window (scripts/web.sh builds it with emscripten).
// The browser owns the loop: emscripten_set_main_loop calls frame() once per display refresh,
// and the browser shows what it drew. The link chooses the scene, method and overlays
// (url_params.h); settings persist in the browser's local storage.
#include "app_config.h"
#include "app_frame.h"
#include "app_setup.h"
#include "audio_out.h"
#include "browser_limits.h"
#include "canvas_web.h"
#include "imgui_ext.h"
#include "link.h"
#include "mouse_tool.h"
#include "options.h"
#include "page_controls.h"
#include "prepared_frame.h"
#include "printable.h"
#include "renderer.h"
#include "spoken_text.h"
#include "touch_input.h"
#include "trace_opening.h"
#include "ui_renderer_gl.h"
#include "ui_style.h"
#include "url_params.h"

#include <emscripten.h>
#include <imgui.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

namespace {

constexpr const char* kSettingsKey = "collision-sandbox/settings";  // AppConfig's text format
constexpr const char* kImGuiIniKey = "collision-sandbox/imgui.ini"; // window placement

struct WebApp {
    App app;
    CanvasWeb canvas;
    SceneRenderer renderer;
    PreparedFrame frame; // worked out, then drawn (one thread: ImGui's draw data not copied)
    AudioOut audio;      // Web Audio, through emscripten's OpenAL
    AppConfig config;
    std::string storedSettings; // what local storage holds, to write only on change
    bool unsavedShown = false;  // what the page was last told (it asks before unloading then)
    // The link the address bar shows (link.h): its query and the scene it carries ("" for none),
    // and when that scene was last made (s on the page's clock).
    std::string linkQuery, linkScene;
    double linkSceneAt = -1e9;
    std::uint64_t linkChanges = 0; // the session's changes when the scene was last made
    double pixelRatio = 1.0; // the ratio app.view.uiScale includes (the user's scale times it)
    TouchInput touch;
    imgui_ext::ScrollTarget touchScrolls; // what a swipe scrolls: the window under the finger
    bool typingShown = false;             // the page's field for the on-screen keyboard has focus
    long long frames = 0;
    double realTime = 0.0;    // s since the first frame (the live region's pace)
    std::string shownState;   // pageStateJson() as the page last got it
    SpokenScreen spoken;      // the screen as the live region last told it (spoken_text.h)
    double stateAt = -1e9;    // realTime when the page's text was last made
    double linkAt = -1e9;     // the page's clock (s) when the link was last looked at
    double settingsAt = -1e9; // realTime when the settings were last looked at
    // Files dropped or picked, opened in turn, each a frame after the page says "Opening ..."
    // (openFilesInTurn); `openingShown`: the page says it for the first one.
    std::deque<std::string> opening;
    bool openingShown = false;
    std::unique_ptr<TraceOpening> traceOpening; // the first in `opening`, compared a run a frame
    std::string saidMessage; // the app's error or note as the page's live region last said it
};

WebApp* gWeb = nullptr;

// The UI scale follows the device pixel ratio (crisp text on high-DPI screens, and the browser's
// zoom scales the UI as Ctrl+= / Ctrl+- do in the window).
void followPixelRatio(WebApp& w) {
    const double ratio = w.canvas.devicePixelRatio;
    if (ratio == w.pixelRatio) return;
    setUiScale(w.app.view, static_cast<float>(w.app.view.uiScale / w.pixelRatio * ratio));
    w.pixelRatio = ratio;
}

// The settings are looked at every kSettingsSeconds rather than every frame (formatting them is
// a good part of a quiet frame's work), and when the page goes away (sandbox_web_save_settings).
constexpr double kSettingsSeconds = 0.5;

void saveSettings(WebApp& w) {
    // Only a shipped scene is there next time (opened, saved and linked ones live in memory).
    for (const SceneEntry& s : w.app.shipped.scenes)
        if (s.path == w.app.sim.scenePath) w.config.lastScene = s.path;
    keepSettings(w.app, w.config, w.pixelRatio);
    w.config.windowWidth = w.canvas.width;
    w.config.windowHeight = w.canvas.height;
    const std::string text = formatAppConfig(w.config);
    if (text != w.storedSettings) storageSet(kSettingsKey, text);
    w.storedSettings = text;
    ImGuiIO& io = ImGui::GetIO();
    if (io.WantSaveIniSettings) {
        storageSet(kImGuiIniKey, ImGui::SaveIniSettingsToMemory());
        io.WantSaveIniSettings = false;
    }
}

// The address bar follows what is on screen (history replaced, never pushed). The scene it
// carries is made again at most every kLinkRefreshSeconds while paused; while the simulation
// runs the blocks move every frame, so the link keeps the scene as it last was when paused.
constexpr double kLinkRefreshSeconds = 0.5;
// The link is looked at every kLinkLookSeconds, not every frame (the page puts it in the address
// bar at most every 400 ms anyway: index.html's setLink).
constexpr double kLinkLookSeconds = 0.25;

void followLink(WebApp& w, double now) {
    if (now - w.linkAt < kLinkLookSeconds) return;
    w.linkAt = now;
    const App& app = w.app;
    std::string scene = w.linkScene;
    if (!linkCarriesScene(app) || linkSceneTooLarge(app)) {
        scene.clear();
    } else if (scene.empty() || app.sim.changes != w.linkChanges ||
               (app.sim.paused && now - w.linkSceneAt >= kLinkRefreshSeconds)) {
        // A change since (an edit, an undo, a block dragged on: each move is an edit) makes it
        // again at once.
        w.linkChanges = app.sim.changes;
        scene = sceneToJson(linkedScene(app));
        w.linkSceneAt = now;
    }
    std::string query = linkQuery(app);
    if (query == w.linkQuery && scene == w.linkScene) return;
    w.linkQuery.swap(query);
    w.linkScene.swap(scene);
    pageSetLink(w.linkQuery, w.linkScene);
}

// Touch (touch_input.h): ImGui's mouse as the fingers say, before ImGui's frame; a swipe
// scrolls the window the finger went down on, a drag from the scene's empty space pans.
void applyTouch(WebApp& w, double now) {
    if (w.canvas.mouseMoved) w.touch.mouseMoved(); // the pointer is the mouse's again
    w.canvas.mouseMoved = false;
    for (const TouchEvent& e : canvasTakeTouches(w.canvas))
        w.touch.event(e.phase, e.id, e.pos, e.time);
    if (!w.touch.active()) return;
    const TouchInput::Frame f = w.touch.frame(now);
    imgui_ext::setPointer(f.pointer,
                          ImVec2(static_cast<float>(f.pos.x), static_cast<float>(f.pos.y)), f.down,
                          f.ctrl);
    if (f.scrollY != 0.0) imgui_ext::scrollBy(w.touchScrolls, -static_cast<float>(f.scrollY));
    if (f.pan.x != 0.0 || f.pan.y != 0.0) touchPanZoom(w.app.view, Vec2{}, f.pan, 1.0);
}

// After ImGui's frame began with the pointer at a finger that just went down: is it on the UI
// (and which window scrolls), or on the scene (on a block, or empty space)?
void resolveTouch(WebApp& w) {
    const TouchInput::Mode mode = w.touch.mode();
    if (mode == TouchInput::Mode::Waiting || mode == TouchInput::Mode::Pending)
        w.touchScrolls = imgui_ext::scrollTargetUnderPointer();
    if (!w.touch.waitingForStart()) return;
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 at{io.MousePos.x, io.MousePos.y};
    w.touch.resolveStart(io.WantCaptureMouse,
                         blockAtScreen(w.app.sim.world(), w.app.view, at) >= 0);
}

// Typing with the on-screen keyboard: while a field takes text after a tap, the page's own text
// field has the focus (the keyboard shows) and hands its characters to ImGui.
void followTyping(WebApp& w) {
    const bool typing = w.touch.active() && ImGui::GetIO().WantTextInput;
    if (typing == w.typingShown) return;
    w.typingShown = typing;
    pageSetTyping(typing);
}

// Requests the app made of its platform, answered by the page.
void answerRequests(WebApp& w) {
    App& app = w.app;
    if (!app.ui.savedFile.empty()) pageDownload(app.ui.savedFile);
    app.ui.savedFile.clear();
    if (app.ui.filePickerRequested) pageOpenFilePicker();
    app.ui.filePickerRequested = false;
    if (app.ui.copyLinkRequested && linkSceneTooLarge(app)) // no link can carry it
        app.ui.messages.error = linkTooManyBlocksMessage(app.sim.world().blocks.size());
    else if (app.ui.copyLinkRequested) // the scene as it is now, running or not
        pageCopyLink(linkQuery(app),
                     linkCarriesScene(app) ? sceneToJson(app.sim.currentScene()) : "");
    app.ui.copyLinkRequested = false;
    if (app.ui.fullscreenRequested) pageToggleFullscreen();
    app.ui.fullscreenRequested = false;
    app.ui.quitRequested = false; // Esc: closing the tab is the browser's
    if (app.sim.unsavedEdits() != w.unsavedShown) {
        w.unsavedShown = !w.unsavedShown;
        pageSetUnsavedEdits(w.unsavedShown);
    }
}

// The page's text for a screen reader is made again every kPageTextSeconds: while the simulation
// runs its status (t) changes every frame, and rewriting the page's text and controls 60 times a
// second cost more than a millisecond per frame (the DOM), which no reader can follow anyway.
constexpr double kPageTextSeconds = 0.25;

// The page's text for a screen reader, kept in step with the canvas (within kPageTextSeconds),
// and through its live region each step entered, its answer, every error (spokenChanges) and the
// collisions (at most about one a second).
void tellPage(WebApp& w, double realSeconds) {
    w.realTime += realSeconds;
    if (w.realTime - w.stateAt >= kPageTextSeconds) {
        w.stateAt = w.realTime;
        SpokenScreen spoken = spokenScreen(w.app); // once: the page's text and the live region's
        std::string state = pageStateJson(w.app, spoken);
        if (state != w.shownState) pageShowState(state);
        w.shownState = std::move(state);
        for (const std::string& line : spokenChanges(w.spoken, spoken)) pageAnnounce(line);
        w.spoken = std::move(spoken);
    }
    const std::string said = w.app.sim.announcer.announce(
        w.realTime, [&](int i) { return w.app.sim.blockDisplayName(i); });
    if (!said.empty()) pageAnnounce(said);
    // The panel's error or note, when it changes, is said too (a refused file, a bad link).
    const Messages& m = w.app.ui.messages;
    const std::string& message = m.error.empty() ? m.note : m.error;
    if (message != w.saidMessage && !message.empty()) pageAnnounce(message);
    w.saidMessage = message;
}

// Files dropped or picked open one at a time: one refused at once when it is larger than the
// browser opens (browser_limits.h: the message names the limit, and the file leaves the
// browser's memory); otherwise the page says "Opening NAME (SIZE)..." for a frame (drawn before
// the work starts, which holds the page's one thread), then it opens: a scene at once, a trace
// compared one run a frame with its progress shown (browser/trace_opening.h).
void openFilesInTurn(WebApp& w) {
    for (std::string& path : canvasTakeOpenedFiles(w.canvas)) w.opening.push_back(std::move(path));
    if (w.opening.empty()) return;
    const std::string path = w.opening.front();
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    const std::string refusal = ec ? std::string() : browserOpenRefusal(path, bytes);
    if (!refusal.empty()) {
        w.app.ui.messages.error = refusal;
        std::filesystem::remove(path, ec);
        w.opening.pop_front();
        return;
    }
    if (!w.openingShown) {
        pageShowProgress(openingMessage(path, ec ? 0 : bytes));
        w.openingShown = true;
        return;
    }
    std::string progress;
    if (!openFileStep(w.app, w.traceOpening, path, progress)) {
        pageShowProgress(progress);
        return;
    }
    pageShowProgress("");
    w.openingShown = false;
    w.opening.pop_front();
}

void runFrame(WebApp& w) {
    App& app = w.app;
    double realSeconds = 0.0;
    canvasNewFrame(w.canvas, &realSeconds);
    followPixelRatio(w);
    app.view.fullscreen = w.canvas.fullscreen;
    app.ui.touchUi = app.ui.touchUi || w.canvas.touchScreen || w.touch.active();
    if (uiFollowView(app.view, app.ui.touchUi)) { // the canvas's height too
        uiRendererFontsChanged();
        uiRendererNewFrame(); // uploads the new atlas before this frame uses it
    }
    openFilesInTurn(w);
    for (const TouchGesture& g : canvasTakeGestures(w.canvas))
        touchPanZoom(app.view, g.from, g.to, g.spreadRatio);
    applyTouch(w, emscripten_get_now() / 1000.0);
    ImGui::NewFrame();
    resolveTouch(w);
    appFrame(app, canvasTakeKeyPresses(w.canvas), realSeconds, true);
    ImGui::Render();
    prepareFrame(app, w.renderer, w.canvas.width, w.canvas.height, w.frame, false);
    drawFrame(w.renderer, w.frame);
    w.audio.play(app.sim.sound);
    answerRequests(w);
    tellPage(w, realSeconds);
    followTyping(w);
    followLink(w, emscripten_get_now() / 1000.0);
    if (w.realTime - w.settingsAt >= kSettingsSeconds) {
        w.settingsAt = w.realTime;
        saveSettings(w);
    }
    if (w.frames++ == 0) pageFirstFrameShown();
}

// After an error in a frame: the page says it (the panel's error and the live region), an ImGui
// frame it left open is closed, and the next frame goes on.
void frameFailed(WebApp& w, const std::string& what) {
    imgui_ext::endFrameLeftOpen(); // an ImGui frame the error left open (imgui_ext.h)
    w.app.ui.messages.error = "The sandbox met an error and goes on: " + printable(what);
    std::fprintf(stderr, "sandbox: %s\n", w.app.ui.messages.error.c_str());
    pageShowProgress("");
    w.opening.clear();
    w.openingShown = false;
    w.traceOpening.reset();
    if (w.frames++ == 0) pageFirstFrameShown();
}

// Every C++ exception reaches the page as a message, and the next frame goes on.
void frame(void* arg) {
    WebApp& w = *static_cast<WebApp*>(arg);
    std::string what;
    try {
        runFrame(w);
        return;
    } catch (const std::exception& e) {
        what = e.what();
    } catch (...) {
        what = "an unknown exception";
    }
    frameFailed(w, what);
}

// The frame inside JavaScript's try. A JavaScript exception (one of the page's services that
// throws) passes C++'s catch (...) by: with WebAssembly's exceptions (-fwasm-exceptions) it
// catches C++'s only. Uncaught, it would end emscripten's main loop (the page frozen on its last
// frame, its message never drawn); here it goes to sandbox_web_frame_failed as C++'s do.
// emscripten's own ('unwind', ExitStatus) pass on, and so do WebAssembly's traps (an access out
// of bounds, unreachable, abort(): a RuntimeError, ABORT set): after one the heap may be corrupt
// and nothing the app would draw could be trusted, so the page stops there as before.
// JavaScript, not C++: kept as written.
// clang-format off
EM_JS(void, run_frame_in_js_try, (std::uintptr_t run, void* arg), {
    try {
        wasmTable.get(run)(arg);
    } catch (e) {
        if (e === 'unwind' || e instanceof ExitStatus || e instanceof WebAssembly.RuntimeError ||
            (typeof ABORT !== 'undefined' && ABORT)) throw e;
        _sandbox_web_frame_failed(allocateUTF8(String((e && e.message) || e)));
    }
});
// clang-format on

void guardedFrame(void* arg) {
    run_frame_in_js_try(reinterpret_cast<std::uintptr_t>(&frame), arg); // its table index
}

// ImGui's keyboard focus for the browser tests: the focused control's id, whether the focus ring
// shows, and its rectangle (framebuffer pixels, where it is drawn).
std::string navigationJson() {
    const imgui_ext::KeyboardFocus f = imgui_ext::keyboardFocus();
    char text[200];
    std::snprintf(text, sizeof text, ",\"navId\":%u,\"navVisible\":%s,\"navRect\":[%d,%d,%d,%d]",
                  f.id, f.ringShown ? "true" : "false", static_cast<int>(f.min.x),
                  static_cast<int>(f.min.y), static_cast<int>(f.max.x), static_cast<int>(f.max.y));
    return text;
}

} // namespace

// Called by run_frame_in_js_try with a JavaScript exception's message (malloc'd: freed here).
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_frame_failed(char* text) {
    const std::string what = text ? text : "";
    std::free(text);
    if (gWeb) frameFailed(*gWeb, "JavaScript: " + what);
}

// Called by web/index.html when the page is hidden or left: the settings are kept now.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_save_settings() {
    if (gWeb) saveSettings(*gWeb);
}

// Called by web/index.html with what the page's text field got from the on-screen keyboard.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_typed(unsigned int codepoint) {
    if (gWeb && codepoint >= 0x20 && codepoint != 0x7f) ImGui::GetIO().AddInputCharacter(codepoint);
}

// Called by web/index.html's first-visit hint: opens the first shipped lesson at its start.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_open_lesson() {
    if (!gWeb || gWeb->app.shipped.lessons.empty()) return;
    openLesson(gWeb->app, gWeb->app.shipped.lessons.front().path);
}

// For the browser tests: the --verbose log on (1) or off, printed to the page's console.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_verbose(int on) {
    if (gWeb) gWeb->app.log.verbose = gWeb->app.sim.verbose = on != 0; // the edits print too
}

// Called by web/index.html's first-visit hint: opens the help (its keys, or on a touch screen its
// gestures).
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_open_help() {
    if (gWeb) gWeb->app.ui.helpOpen = true;
}

// Called by web/index.html before it reads a picked file: 1 when the browser does not open a
// file of that name and size (browser_limits.h; the panel and the live region then say why and
// the page never reads it), else 0.
extern "C" EMSCRIPTEN_KEEPALIVE int sandbox_web_refuse_file(const char* name, double bytes) {
    if (!gWeb || !name) return 0;
    const std::string refusal =
        browserOpenRefusal(name, bytes > 0.0 ? static_cast<std::uintmax_t>(bytes) : 0u);
    if (refusal.empty()) return 0;
    gWeb->app.ui.messages.error = refusal;
    return 1;
}

// Called by web/index.html for an error of the page's own (an uncaught exception or rejection):
// the panel and the live region say it.
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_page_error(const char* text) {
    if (gWeb && text)
        gWeb->app.ui.messages.error = "The page met an error: " + printable(text, 300);
}

// Called by web/index.html when "Copy link" is done: the note, or the error (a link too long).
extern "C" EMSCRIPTEN_KEEPALIVE void sandbox_web_link_copied(int chars, int copied) {
    if (!gWeb) return;
    App& app = gWeb->app;
    if (chars > static_cast<int>(kMaxLinkChars))
        app.ui.messages.error = linkTooLongMessage(static_cast<std::size_t>(chars));
    else if (copied)
        app.ui.messages.note = "Link copied (" + std::to_string(chars) + " characters)";
    else
        app.ui.messages.error =
            "The browser did not let the page copy the link: it is in the address bar.";
}

// For the browser tests and the page: the app's state as JSON (scene, method, paused, frames,
// error, the open trace's first difference). The text lives until the next call.
extern "C" EMSCRIPTEN_KEEPALIVE const char* sandbox_web_status() {
    static std::string text;
    if (!gWeb) return "{}";
    const App& app = gWeb->app;
    auto exact = [](double v) { // every digit, so a test compares exactly (null: infinite)
        if (!std::isfinite(v)) return std::string("null");
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        return std::string(buffer);
    };
    auto quoted = [](const std::string& s) {
        std::string out = "\"";
        for (const char c : s) {
            if (c == '"' || c == '\\') out += '\\';
            if (static_cast<unsigned char>(c) < 0x20)
                out += ' ';
            else
                out += c;
        }
        return out + "\"";
    };
    text = "{\"scene\":" + quoted(app.sim.scenePath) +
           ",\"method\":" + quoted(methodName(app.sim.world().settings.method)) +
           ",\"paused\":" + (app.sim.paused ? "true" : "false") +
           ",\"frames\":" + std::to_string(gWeb->frames) +
           ",\"simTime\":" + std::to_string(app.sim.world().time) +
           ",\"error\":" + quoted(app.ui.messages.error) +
           ",\"plots\":" + (app.view.show.plots ? "true" : "false") +
           ",\"inspector\":" + (app.view.show.inspector ? "true" : "false") + ",\"lessonStep\":" +
           (app.lesson.active() ? std::to_string(app.lesson.current + 1) : std::string("0")) +
           ",\"pixelsPerMetre\":" + exact(app.view.camera.pixelsPerMetre()) +
           ",\"unsaved\":" + (app.sim.unsavedEdits() ? "true" : "false") +
           ",\"note\":" + quoted(app.ui.messages.note) +
           ",\"fullscreen\":" + (app.view.fullscreen ? "true" : "false") +
           ",\"helpOpen\":" + (app.ui.helpOpen ? "true" : "false") +
           ",\"slowMotion\":" + (app.sim.slowMotion ? "true" : "false") +
           ",\"presentMode\":" + (app.view.presentMode ? "true" : "false") +
           ",\"keyboardWindow\":" + quoted(app.ui.keyboardWindow) +
           ",\"traceFirstDifference\":" + // null: no trace open; -1: the same as the reference
           (app.studentTrace.open() ? std::to_string(app.studentTrace.firstDifference())
                                    : std::string("null"));
    // Each block: its state ([x, y, vx, vy, width, height, mass], every digit) and where it is
    // drawn ([left, top, width, height] in CSS pixels).
    const double ratio = gWeb->canvas.devicePixelRatio;
    std::string blocks, onScreen;
    for (const Block& b : app.sim.world().blocks) {
        blocks += std::string(blocks.empty() ? "" : ",") + "[" + exact(b.position.x) + "," +
                  exact(b.position.y) + "," + exact(b.velocity.x) + "," + exact(b.velocity.y) +
                  "," + exact(b.size.x) + "," + exact(b.size.y) + "," + exact(b.mass) + "]";
        const Vec2 corner = app.view.camera.worldToScreen(b.position - b.size * 0.5);
        const double ppm = app.view.camera.pixelsPerMetre();
        onScreen += std::string(onScreen.empty() ? "" : ",") + "[" + exact(corner.x / ratio) + "," +
                    exact((corner.y - b.size.y * ppm) / ratio) + "," +
                    exact(b.size.x * ppm / ratio) + "," + exact(b.size.y * ppm / ratio) + "]";
    }
    auto rect = [&](const ScreenRect& r) { // in CSS pixels
        return "[" + exact(r.x / ratio) + "," + exact(r.y / ratio) + "," + exact(r.width / ratio) +
               "," + exact(r.height / ratio) + "]";
    };
    // The world's bounds where they are drawn (CSS pixels).
    const Bounds& bounds = app.sim.world().bounds;
    const Vec2 low = app.view.camera.worldToScreen(bounds.min);
    const Vec2 high = app.view.camera.worldToScreen(bounds.max);
    const ScreenRect world{low.x, high.y, high.x - low.x, low.y - high.y};
    const ImGuiIO& io = ImGui::GetIO();
    text += ",\"blocks\":[" + blocks + "],\"blocksOnScreen\":[" + onScreen +
            "],\"worldOnScreen\":" + rect(world) +
            ",\"sceneOnScreen\":" + rect(app.view.layout.scene) +
            ",\"panelOnScreen\":" + rect(app.view.layout.panel) +
            ",\"sheet\":" + (app.view.layout.sheet ? "true" : "false") +
            ",\"sheetOpen\":" + (app.view.sheetOpen ? "true" : "false") +
            ",\"touchUi\":" + (app.ui.touchUi ? "true" : "false") +
            ",\"frameHeight\":" + exact(ImGui::GetFrameHeight() / ratio) +
            ",\"bouncinessSlider\":" + rect(app.ui.bouncinessSlider) +
            ",\"bounciness\":" + exact(app.sim.world().settings.bounciness) + ",\"gravity\":[" +
            exact(app.sim.world().settings.gravity.x) + "," +
            exact(app.sim.world().settings.gravity.y) + "]" +
            ",\"pointerOnScreen\":" + (ImGui::IsMousePosValid(&io.MousePos) ? "true" : "false") +
            ",\"typing\":" + (io.WantTextInput ? "true" : "false") +
            ",\"captionHeight\":" + exact(app.view.captionHeight / ratio) +
            ",\"lessonPhase\":" + std::to_string(static_cast<int>(app.lesson.phase)) +
            ",\"revealed\":" + (app.lesson.revealed ? "true" : "false") + navigationJson() + "}";
    return text.c_str();
}

// The page's own form controls (page_controls.h): a control set to `value`. Returns "" or why
// the value was refused (the page shows it beside the control).
extern "C" EMSCRIPTEN_KEEPALIVE const char* sandbox_web_control(const char* control,
                                                                const char* value) {
    static std::string error;
    if (!gWeb) return "";
    const PageControlOutcome out = applyPageControl(gWeb->app, control, value);
    applyAction(gWeb->app, out.action);
    error = out.error;
    return error.c_str();
}

int main() {
    static WebApp w; // lives as long as the page: the loop never returns
    gWeb = &w;
    App& app = w.app;
    w.storedSettings = storageGet(kSettingsKey);
    w.config = parseAppConfig(w.storedSettings);
    UrlParams params = parseUrlParams(pageQueryString());
    params.linkScene = pageLinkScene();
    std::string error;
    setupApp(app, Options{}, w.config.lastScene, &error);
    applyUrlParams(app, params);
    const std::string linkError = pageLinkError();
    if (!linkError.empty())
        app.ui.messages.error += (app.ui.messages.error.empty() ? "" : "\n") + linkError;
    app.ui.inBrowser = true;
    std::error_code ec;
    std::filesystem::create_directories(kBrowserDownloads, ec); // Save writes there

    uiCreateContext(nullptr);
    const std::string ini = storageGet(kImGuiIniKey);
    if (!ini.empty()) ImGui::LoadIniSettingsFromMemory(ini.c_str(), ini.size());
    if (!canvasInit(w.canvas, &error)) {
        std::fprintf(stderr, "sandbox: %s\n", error.c_str());
        return 1;
    }
    w.pixelRatio = w.canvas.devicePixelRatio;
    applyStartSettings(app, w.config, Options{}, w.pixelRatio);
    uiFollowView(app.view, app.ui.touchUi);
    uiRendererFontsChanged();
    if (!w.renderer.init(&error)) app.ui.messages.error = "Shader error: " + error;
    emscripten_set_main_loop_arg(guardedFrame, &w, 0, 1);
    return 0;
}
