#!/usr/bin/python3
"""The browser build in a real browser: headless Chromium (Debian's chromium, WebGL 2 on the CPU
through SwiftShader) opens build-web/index.html from a local server and is driven over the
DevTools protocol (python3-websocket). One check per run:

  first-frame   the first frame draws the default scene: a screenshot with many colours, the
                controls panel visible, the default scene loaded; the first visit's hint shows,
                goes when dismissed and stays gone after a reload; its button opens the lesson
  pause         P pauses: two screenshots taken frames apart are equal (and were not before)
  url-scene     ?scene=newtons_cradle&method=turn-based&show=plots,inspector selects them
  url-lesson    ?lesson=lecture3&step=5 opens the lesson at step 5
  url-bad       bad URL parameters show their errors in the panel and keep the default scene
  open-file     a picked or dropped file opens; a bad one shows its error (with its place) and
                keeps the current scene; a student's trace (.csv) opens at its first difference
  wheel         one wheel notch up over the scene zooms in by one step (x1.15, as the desktop's
                wheel), one down zooms out by one, 3 lines (Firefox) are one notch; a notch over
                the panel scrolls it and leaves the zoom alone
  fullscreen    at device pixel ratio 1 and 2, entering and leaving full screen (the page becomes
                exactly screen-sized) leaves the canvas's size = its CSS size x the ratio, and no
                uncaught error
  trackers      ?utm_source=x&fbclid=y shows no error
  phone         390x844 at ratio 3 with touch: the panel is a sheet along the bottom; closed, the
                scene has >= 60% of the screen and shows the whole default scene (every block);
                controls are >= 44 CSS px high (the first visit's hint's buttons too, and it goes
                at the first tap); a tap opens the sheet, a swipe over a slider
                scrolls it and leaves every setting as it was (and nothing hovered after); a tap
                on the slider opens it for typing with the on-screen keyboard, and 0.5 typed
                there is taken; a tap closes the sheet
  offline       the one-file build (sandbox-offline.html) opened as file:// draws the default
                scene; the folder build opened as file:// says what to do; served, the page
                keeps working once the server is gone (the service worker)
  link          the address bar follows an edit (a block dragged, the method changed) with the
                scene in its fragment; opening that link in a new browser restores exactly those
                blocks and that method; a damaged fragment is an error naming it, and a scene too
                large for a link says so
  unsaved       no question before leaving at first; after an edit (a block dragged) the page
                asks (beforeunload); Ctrl+S downloads the scene named after it
  axe           axe-core (npm, injected into the page) finds no violation at the first frame
                and with a lesson open
  live-region   lecture_example_1 played (with the page's own Play button) through its
                collision leaves the live region saying it in the inspector's words; the page's
                text names the scene and the lesson's step; lecture3 step 3 with C set to 0.9
                through the page's control says "bounciness C is now 0.90; the question now
                reads: Predict: ... C = 0.9 ..."
  hidden-control  the page's hidden C control sets the world's C; a refused value is said
  undo          the page's hidden Undo and Redo buttons take C back and set it again (the note
                says "undo: bounciness 0.25 -> 1.00"); a block dragged on the canvas is one edit:
                Ctrl+Z puts it back where it was, bit for bit, Ctrl+Y moves it again
  sound         M turns the sound on and lecture_example_1's collision plays a knock through
                emscripten's OpenAL (a source of its Web Audio context has played)
  keyboard      F6, then the arrow keys, walk through at least 15 of the panel's controls, each
                with the focus ring shown around it (keyboard_focus.png in the temporary folder,
                for looking)
  keys          the lecture's keys whatever has the focus, as SandboxWindowXvfbKeys in the window,
                checked through the --verbose log (the page's console): on lecture3, the C slider
                clicked, then typed into (the digits and Enter the field's; Esc undoes; F5 and
                PageDown act and leave the field), then Right three
                times, Space, 1 3 Enter, S, Shift+R step the lesson, slow down, jump, change the
                method and restore the step, and nothing else (no focus ring, the keyboard the
                scene's); F5 is present mode and never reloads the page; F6 gives the panel the
                keyboard (the ring shows), Esc gives it back; Tab leaves the canvas for the page's
                own controls (the app never sees it) and Shift+Tab comes back; on step 26 the
                arrows drive the player
  shots DIR     writes screenshots into DIR to look at (docs/web/): 390x844 (a phone, the panel
                closed and open), 1024x768 (a tablet), 1366x768 (a laptop), 1280x720 and
                1920x1080 (projectors)

Every check also fails on any console error or uncaught exception of the page. Exit 0: passed;
1: failed; 77: skipped (no chromium, no python3-websocket or no build-web/: ctest SKIP).
Timeouts only guard against a hang; nothing is timed.

usage: browser_test.py SITE_DIR CHECK [ARGS]
"""
import base64
import functools
import http.server
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

SKIP = 77
# The keyboard check's picture of the focus ring, for looking (outside the source tree).
FOCUS_SHOT = os.path.join(tempfile.gettempdir(), "keyboard_focus.png")
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
HANG_GUARD_S = 120  # the longest any wait may take before the check fails as hung
# axe-core, as scripts/web.sh installs it (npm) into its cache.
AXE_JS = os.environ.get("SANDBOX_AXE_JS") or os.path.join(
    os.environ.get("SANDBOX_WEB_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "collision-sandbox"),
    "npm", "node_modules", "axe-core", "axe.min.js")


def skip(why):
    print(f"SKIP: {why}")
    sys.exit(SKIP)


try:
    import websocket  # python3-websocket
    from PIL import Image  # python3-pil
except ImportError as e:
    skip(f"{e.name} is not installed (scripts/web.sh deps installs python3-websocket and python3-pil)")


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                      ".wasm": "application/wasm", ".js": "text/javascript"}

    def log_message(self, *args):
        pass


def serve(site):
    """`site` served on 127.0.0.1 (a free port) from a thread: the server, and its index.html's
    URL (the browser tests, the big-input tests and the frame benchmark)."""
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(QuietHandler, directory=site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/index.html"


class Page:
    """One Chromium with one page, over the DevTools protocol (`flags`: more of Chromium's
    switches)."""

    def __init__(self, width, height, pixel_ratio=1.0, touch=False, flags=()):
        self.profile = tempfile.mkdtemp(prefix="sandbox-chromium-")
        self.proc = subprocess.Popen(
            [CHROMIUM, "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--no-first-run", "--no-default-browser-check",
             "--disable-extensions", "--hide-scrollbars", "--mute-audio",
             f"--window-size={width},{height}", f"--force-device-scale-factor={pixel_ratio}",
             "--remote-debugging-port=0",
             f"--user-data-dir={self.profile}", *flags, "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(self.profile, "DevToolsActivePort")
        self.wait(lambda: os.path.exists(port_file) and open(port_file).read().count("\n") >= 1,
                  "Chromium's DevTools port")
        port = int(open(port_file).read().split("\n")[0])
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
        page = next(t for t in targets if t["type"] == "page")
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=HANG_GUARD_S)
        self.next_id = 0
        self.errors = []
        self.logs = []  # the page's console.log lines (the app's stdout: --verbose)
        self.dialogs = []  # the types of the dialogs the page opened (accepted)
        self.call("Runtime.enable")
        self.call("Log.enable")
        self.call("Page.enable")
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
                  deviceScaleFactor=pixel_ratio, mobile=touch)
        if touch:  # a phone or tablet: a touch screen, no mouse
            self.call("Emulation.setTouchEmulationEnabled", enabled=True, maxTouchPoints=5)

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
            shutil.rmtree(self.profile, ignore_errors=True)

    @staticmethod
    def wait(condition, what):
        deadline = time.monotonic() + HANG_GUARD_S
        while not condition():
            if time.monotonic() > deadline:
                raise AssertionError(f"gave up waiting for {what}")
            time.sleep(0.05)

    def note_event(self, message):
        method, params = message.get("method"), message.get("params", {})
        if method == "Page.javascriptDialogOpening":  # "leave with unsaved edits?": yes
            self.dialogs.append(params.get("type"))
            self.next_id += 1
            self.ws.send(json.dumps({"id": self.next_id, "method": "Page.handleJavaScriptDialog",
                                     "params": {"accept": True}}))
        if method == "Runtime.consoleAPICalled" and params.get("type") == "log":
            self.logs.extend(" ".join(str(a.get("value", "")) for a in params["args"])
                             .split("\n"))
        if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            self.errors.append(f"console.error: {text}")
        elif method == "Runtime.exceptionThrown":
            d = params["exceptionDetails"]
            self.errors.append(f"exception: {d.get('exception', {}).get('description', d['text'])}")
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            self.errors.append(f"log: {params['entry']['text']} {params['entry'].get('url', '')}")

    def call(self, method, **params):
        self.next_id += 1
        my_id = self.next_id
        self.ws.send(json.dumps({"id": my_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.ws.recv())
            if message.get("id") == my_id:
                if "error" in message:
                    raise AssertionError(f"{method}: {message['error']}")
                return message.get("result", {})
            self.note_event(message)

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in result:
            raise AssertionError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def evaluate_async(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                           awaitPromise=True)
        if "exceptionDetails" in result:
            raise AssertionError(f"{expression[:200]}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def status(self):
        text = self.evaluate("window.sandboxFirstFrame === undefined ? null : "
                             "Module.ccall('sandbox_web_status', 'string', [], [])")
        return json.loads(text) if text else None

    def open(self, url):
        self.call("Page.navigate", url=url)
        self.wait(lambda: self.status() is not None, "the first frame")

    def wait_frames(self, count):
        start = self.status()["frames"]
        self.wait(lambda: self.status()["frames"] >= start + count, f"{count} more frames")

    def screenshot(self):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        return base64.b64decode(data)

    def key(self, key, code, key_code, ctrl=False, shift=False, kinds=("keyDown", "keyUp"),
            text=None):
        # Emscripten's GLFW knows Ctrl and Shift from their own keys' presses, as a keyboard
        # sends them. `text`: the character the key types (a keypress: a text field's input).
        control = dict(key="Control", code="ControlLeft", windowsVirtualKeyCode=17,
                       nativeVirtualKeyCode=17)
        shift_key = dict(key="Shift", code="ShiftLeft", windowsVirtualKeyCode=16,
                         nativeVirtualKeyCode=16)
        modifiers = (2 if ctrl else 0) | (8 if shift else 0)
        if ctrl:
            self.call("Input.dispatchKeyEvent", type="rawKeyDown", modifiers=2, **control)
        if shift:
            self.call("Input.dispatchKeyEvent", type="rawKeyDown", modifiers=modifiers, **shift_key)
        for kind in kinds:
            typed = dict(text=text) if text and kind == "keyDown" else {}
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=code,
                      modifiers=modifiers, windowsVirtualKeyCode=key_code,
                      nativeVirtualKeyCode=key_code, **typed)
        if shift:
            self.call("Input.dispatchKeyEvent", type="keyUp", modifiers=modifiers & 2, **shift_key)
        if ctrl:
            self.call("Input.dispatchKeyEvent", type="keyUp", **control)

    def mouse(self, kind, x, y, buttons=0, **extra):
        """A mouse event at (x, y) CSS pixels: mouseMoved, mousePressed, mouseReleased or
        mouseWheel (deltaX, deltaY)."""
        button = "left" if kind in ("mousePressed", "mouseReleased") else "none"
        self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button=button,
                  buttons=buttons, clickCount=1 if button == "left" else 0, **extra)

    def drag(self, x0, y0, x1, y1, steps=5):
        self.mouse("mouseMoved", x0, y0)
        self.wait_frames(1)
        self.mouse("mousePressed", x0, y0, buttons=1)
        self.wait_frames(1)
        for i in range(1, steps + 1):
            self.mouse("mouseMoved", x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps,
                       buttons=1)
            self.wait_frames(1)
        self.mouse("mouseReleased", x1, y1)
        self.wait_frames(2)

    def fingers(self, path):
        """One finger along `path` [(x, y), ...] CSS pixels: down at the first point, moved
        through the others, up at the last, all at once. (The DevTools protocol's own touch
        events wait for a frame each, and a frame at 390x844 x3 on SwiftShader can take a second:
        a finger resting that long would be a hold.) As in a browser, a pointerdown comes first."""
        points = json.dumps(path)
        self.evaluate(f"""(() => {{
            const path = {points}, r = canvas.getBoundingClientRect();
            const touch = ([x, y]) => new Touch({{identifier: 1, target: canvas,
                clientX: r.left + x, clientY: r.top + y}});
            const send = (type, t, down) => canvas.dispatchEvent(new TouchEvent(type, {{
                bubbles: true, cancelable: true, changedTouches: [t], touches: down ? [t] : [],
                targetTouches: down ? [t] : []}}));
            canvas.dispatchEvent(new PointerEvent('pointerdown', {{bubbles: true,
                pointerType: 'touch', clientX: r.left + path[0][0], clientY: r.top + path[0][1]}}));
            send('touchstart', touch(path[0]), true);
            for (const p of path.slice(1)) send('touchmove', touch(p), true);
            send('touchend', touch(path[path.length - 1]), false);
        }})()""")
        self.wait_frames(5)

    def tap(self, x, y):
        self.fingers([(x, y)])

    def swipe(self, x0, y0, x1, y1, steps=8):
        self.fingers([(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps)
                      for i in range(steps + 1)])

    def reload(self):
        """Loads the page again and waits for its new first frame."""
        self.evaluate("window.sandboxOldPage = true")
        self.call("Page.reload")

        def new_page_shown():
            try:
                return self.evaluate("window.sandboxOldPage === undefined && "
                                     "window.sandboxFirstFrame !== undefined")
            except AssertionError as e:  # asked while the old page went: ask the new one
                if "navigated or closed" in str(e):
                    return False
                raise

        self.wait(new_page_shown, "the first frame after reloading")

    def canvas_size(self):
        """The canvas's backing store, its CSS size times the ratio (rounded), and the ratio."""
        return self.evaluate("(() => { const r = canvas.getBoundingClientRect(); "
                             "const d = devicePixelRatio; return [canvas.width, canvas.height, "
                             "Math.round(r.width * d), Math.round(r.height * d), d]; })()")


def image(png):
    return Image.open(io.BytesIO(png)).convert("RGB")


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def colour_count(img):
    return len(img.getcolors(maxcolors=1 << 20) or [])


def panel_visible(img):
    """The controls panel: its title bar (ImGui TitleBg 0.16, 0.29, 0.48) across the top left,
    and its window background (0.105, 0.113, 0.140) below it."""
    title = img.getpixel((200, 10))
    body = img.getpixel((345, 400))
    near = lambda a, b: all(abs(x - y) <= 3 for x, y in zip(a, b))
    return near(title, (41, 74, 122)) and near(body, (27, 29, 36)), (title, body)


def first_frame(page, base):
    page.open(base)
    png = page.screenshot()
    img = image(png)
    colours = colour_count(img)
    check(colours >= 300, f"the first frame has only {colours} colours")
    ok, seen = panel_visible(img)
    check(ok, f"the controls panel is not visible (title, body pixels: {seen})")
    status = page.status()
    check(status["scene"].endswith("/bouncing_squares.json"), f"default scene? {status}")
    check(status["error"] == "", f"the panel shows an error: {status['error']}")
    print(f"first frame: {colours} colours, panel visible, {status['scene']}; shown "
          f"{page.evaluate('window.sandboxFirstFrame'):.0f} ms after the page started loading "
          "(reported, not checked)")
    # The first visit's hint: there, dismissed, and not there the next time.
    hint = "!document.getElementById('hint').hidden"
    check(page.evaluate(hint), "no first-visit hint")
    words = page.evaluate("document.getElementById('hint').innerText")
    check("F1" in words, f"the desktop's hint does not name F1: {words!r}")
    # Its Help button opens the help (and puts the hint away).
    page.evaluate("document.getElementById('hint-help').click()")
    check(page.status()["helpOpen"], "the hint's Help button did not open the help")
    check(not page.evaluate(hint), "the hint stays after its Help button")
    page.evaluate("document.getElementById('hint').hidden = false")
    # It lies beside the panel (covering none of its controls), inside the page.
    box = page.evaluate("(() => { const r = document.getElementById('hint')"
                        ".getBoundingClientRect(); return [r.left, r.right, r.bottom]; })()")
    panel = page.status()["panelOnScreen"]
    check(box[0] >= panel[0] + panel[2] and box[1] <= 1280 and box[2] <= 720,
          f"the hint {box} is over the panel {panel} or off the page")
    page.evaluate("document.getElementById('hint-close').click()")
    check(not page.evaluate(hint), "the hint was not dismissed")
    page.reload()
    check(not page.evaluate(hint), "the dismissed hint came back")
    page.evaluate("document.getElementById('hint').hidden = false; "
                  "document.getElementById('hint-lesson').click()")
    page.wait_frames(3)
    check(page.status()["lessonStep"] == 1, "the hint's button did not open the lesson")
    print("the first visit's hint shows, goes when dismissed, stays gone; it opens the lesson")


def pause(page, base):
    # Scenes open paused at t = 0 (issue 15): the first P plays, the second pauses.
    page.open(base)
    check(page.status()["paused"], "the scene does not open paused")
    page.key("p", "KeyP", 80)
    page.wait_frames(3)
    check(not page.status()["paused"], "P did not start the scene")
    a = page.screenshot()
    page.wait_frames(5)
    b = page.screenshot()
    check(a != b, "the scene does not move after P (the pause check could not fail)")
    page.key("p", "KeyP", 80)
    page.wait_frames(3)
    check(page.status()["paused"], "P did not pause")
    a = page.screenshot()
    page.wait_frames(10)
    b = page.screenshot()
    check(a == b, "two screenshots 10 frames apart differ after P")
    print("P plays and pauses: screenshots differ while playing, equal while paused")


def url_scene(page, base):
    page.open(base + "?scene=newtons_cradle&method=turn-based&show=plots,inspector")
    s = page.status()
    check(s["scene"].endswith("/newtons_cradle.json"), f"scene not selected: {s}")
    check(s["method"] == "turn-based", f"method not selected: {s}")
    check(s["plots"] and s["inspector"], f"overlays not shown: {s}")
    check(s["error"] == "", f"error: {s['error']}")
    print(f"URL parameters: {s}")


def url_lesson(page, base):
    page.open(base + "?lesson=lecture3&step=5")
    s = page.status()
    check(s["lessonStep"] == 5, f"lesson step not selected: {s}")
    check(s["error"] == "", f"error: {s['error']}")
    print(f"URL lesson parameters: {s}")


def url_bad(page, base):
    page.open(base + "?scene=no_such_scene&method=fastest")
    s = page.status()
    check(s["scene"].endswith("/bouncing_squares.json"), f"the default scene was not kept: {s}")
    check("URL parameter method: 'fastest' must be perfect" in s["error"], f"no method error: {s}")
    check("no scene 'no_such_scene'" in s["error"], f"no scene error: {s}")
    check(s["method"] == "perfect", f"method changed: {s}")
    print(f"bad URL parameters shown: {s['error']!r}")


def open_file(page, base):
    page.open(base)

    def pick(name, text_js):
        # What the page's file picker does with the chosen file (index.html).
        page.evaluate(f"FS.mkdirTree('/opened'); FS.writeFile('/opened/{name}', {text_js}); "
                      f"Module.ccall('sandbox_web_file_opened', null, ['string'], ['/opened/{name}'])")
        page.wait_frames(2)
        return page.status()

    s = pick("broken.json", "'{\\n  \"version\": 1,\\n  \"blocks\": [ oops'")
    check(s["scene"].endswith("/bouncing_squares.json"), f"a bad file replaced the scene: {s}")
    check("broken.json" in s["error"] and ":3:" in s["error"], f"no error with its place: {s}")
    s = pick("cradle.json", "FS.readFile('/scenes/newtons_cradle.json')")
    check(s["scene"] == "/opened/cradle.json", f"the picked file did not open: {s}")
    check(s["error"] == "", f"error after a good file: {s}")
    print("a bad file shows its error and keeps the scene; a good one opens")

    # A student's trace (a .csv, docs/compare.md) opens on the current scene: point_of_impact's
    # mover as the reference moves it for four frames, then left unresolved in the fifth.
    s = pick("point_of_impact.json", "FS.readFile('/scenes/point_of_impact.json')")
    check(s["error"] == "" and s["traceFirstDifference"] is None, f"no scene or a trace: {s}")
    rows = ["t,mover_x,mover_y,mover_vx,mover_vy"]
    for k in range(1, 6):  # dt 0.1 s, velocity (14, -14) m/s from (3, 9.5)
        rows.append(f"{k / 10:g},{3 + 1.4 * k:g},{9.5 - 1.4 * k:g},14,-14")
    pick("my_trace.csv", json.dumps("\n".join(rows) + "\n"))
    # The page compares the trace one simulated run a frame, its progress on the page (issue 41):
    # wait for the comparison's outcome, a first difference or an error.
    def compared():
        t = page.status()
        return t["traceFirstDifference"] is not None or t["error"] != ""

    page.wait(compared, "the trace's comparison")
    s = page.status()
    check(s["error"] == "", f"error after a good trace: {s}")
    check(s["traceFirstDifference"] == 5, f"the first difference is not frame 5: {s}")
    check(s["paused"] and s["simTime"] > 0.45, f"the run did not stop at the difference: {s}")
    s = pick("bad_trace.csv", json.dumps("t,mover_x,mover_y,mover_vx,mover_vy\n0.1,abc,8.1,14,-14\n"))
    check("bad_trace.csv:2:5" in s["error"] and "mover_x" in s["error"], f"no place: {s}")
    check(s["traceFirstDifference"] == 5, f"a bad trace replaced the open one: {s}")
    print("a trace opens on the scene at its first difference; a bad one shows its place")


def wheel(page, base):
    page.open(base)
    page.wait_frames(2)
    scene = page.status()["sceneOnScreen"]
    x, y = scene[0] + scene[2] / 2, scene[1] + scene[3] / 2
    page.mouse("mouseMoved", x, y)
    page.wait_frames(2)

    def zoom_after(send):
        before = page.status()["pixelsPerMetre"]
        send()
        page.wait_frames(3)
        return page.status()["pixelsPerMetre"] / before

    # One notch as Chromium reports it: deltaY -100 is the wheel turned up, away from the user.
    up = zoom_after(lambda: page.mouse("mouseWheel", x, y, deltaX=0, deltaY=-100))
    check(abs(up - 1.15) < 1e-9, f"one notch up zoomed by x{up} (one step in: x1.15)")
    down = zoom_after(lambda: page.mouse("mouseWheel", x, y, deltaX=0, deltaY=100))
    check(abs(down - 1 / 1.15) < 1e-9, f"one notch down zoomed by x{down} (one step out)")
    lines = zoom_after(lambda: page.evaluate(
        f"canvas.dispatchEvent(new WheelEvent('wheel', {{deltaY: 3, deltaMode: 1, clientX: {x}, "
        f"clientY: {y}, bubbles: true, cancelable: true}}))"))
    check(abs(lines - 1 / 1.15) < 1e-9, f"3 lines down zoomed by x{lines} (one step out)")
    # Over the panel (its lower part, below Play and Reset), a notch scrolls the panel.
    page.evaluate("document.querySelector('canvas').focus()")
    px, py = 150, 600
    page.mouse("mouseMoved", px, py)
    page.wait_frames(2)
    shot_before = image(page.screenshot()).crop((0, 200, 340, 720))
    panel = zoom_after(lambda: page.mouse("mouseWheel", px, py, deltaX=0, deltaY=100))
    shot_after = image(page.screenshot()).crop((0, 200, 340, 720))
    check(panel == 1.0, f"a notch over the panel zoomed the scene (x{panel})")
    check(shot_before != shot_after, "a notch over the panel did not scroll it")
    print(f"wheel: up x{up:.6f}, down x{down:.6f}, 3 lines x{lines:.6f}, over the panel the "
          "panel scrolled and the zoom stayed")


def fullscreen(base, ratio):
    """Full screen at `ratio`: a 1024x768 screen, a 1024x700 page that becomes 1024x768."""
    page = Page(1024, 700, ratio)
    try:
        def metrics(height):
            page.call("Emulation.setDeviceMetricsOverride", width=1024, height=height,
                      deviceScaleFactor=ratio, mobile=False, screenWidth=1024, screenHeight=768)

        def sized(what):
            page.wait_frames(3)
            w, h, want_w, want_h, d = page.canvas_size()
            check((w, h) == (want_w, want_h) and d == ratio,
                  f"{what} at ratio {ratio}: canvas {w}x{h}, CSS size x ratio {want_w}x{want_h}")
            return f"{w}x{h}"

        metrics(700)
        page.open(base)
        windowed = sized("windowed")
        page.key("F11", "F11", 122)  # the app's key: it asks the page for full screen
        page.wait(lambda: page.evaluate("!!document.fullscreenElement"), "full screen")
        metrics(768)  # what the browser does: the page becomes the screen
        full = sized("full screen")
        check(page.status()["fullscreen"], "the app does not know it is full screen")
        page.key("Escape", "Escape", 27)  # the app leaves full screen
        page.wait(lambda: not page.evaluate("!!document.fullscreenElement"), "leaving full screen")
        metrics(700)
        back = sized("after full screen")
        page.wait_frames(2)
        check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
        print(f"ratio {ratio}: canvas {windowed}, full screen {full}, after {back}")
    finally:
        page.close()


def trackers(page, base):
    page.open(base + "?utm_source=x&fbclid=y")
    s = page.status()
    check(s["error"] == "", f"the panel shows an error: {s['error']}")
    check(s["scene"].endswith("/bouncing_squares.json"), f"default scene? {s}")
    print("?utm_source=x&fbclid=y: no error")


def unsaved(page, base):
    page.open(base)
    asks = ("(() => { const e = new Event('beforeunload', {cancelable: true}); "
            "window.dispatchEvent(e); return e.defaultPrevented; })()")
    check(not page.evaluate(asks), "the page asks before leaving with nothing edited")
    block = page.status()["blocksOnScreen"][0]
    x, y = block[0] + block[2] / 2, block[1] + block[3] / 2
    page.drag(x, y, x + 60, y + 30)
    s = page.status()
    check(s["unsaved"], f"dragging a block is not an unsaved edit: {s['note']}")
    check(page.evaluate(asks), "after an edit the page does not ask before leaving")
    # Ctrl+S downloads the scene, named after it.
    page.evaluate("window.downloadNames = []; HTMLAnchorElement.prototype.click = function () "
                  "{ window.downloadNames.push(this.download); };")
    page.key("s", "KeyS", 83, ctrl=True)
    page.wait_frames(3)
    names = page.evaluate("window.downloadNames")
    check(names == ["bouncing_squares.json"], f"Ctrl+S downloaded {names}")
    check(not page.status()["unsaved"], "still unsaved after the download")
    check(not page.evaluate(asks), "the page still asks after the download")
    print(f"beforeunload asks after a drag, not before; Ctrl+S downloaded {names[0]}")


def link(page, base):
    page.open(base)
    block = page.status()["blocksOnScreen"][0]
    x, y = block[0] + block[2] / 2, block[1] + block[3] / 2
    page.key("s", "KeyS", 83)  # the next method: move-and-correct
    page.wait(lambda: "method=move-and-correct" in page.evaluate("location.search"),
              "the address bar to follow the method")
    page.drag(x, y, x + 80, y - 40)  # now the link carries the scene, the method inside it
    page.wait(lambda: "#scene=" in page.evaluate("location.href") and
              "method=" not in page.evaluate("location.search"), "the address bar to follow")
    # The address bar may have caught the drag on its way: it settles on where the block stopped.
    settled = ""
    for _ in range(20):
        href = page.evaluate("location.href")
        if href == settled:
            break
        settled = href
        page.wait_frames(60)
    edited = page.status()
    check(edited["method"] == "move-and-correct", f"S did not change the method: {edited}")
    url = page.evaluate("location.href")
    check(len(url) <= 32000, f"the link is {len(url)} characters")
    other = Page(1280, 720)
    try:
        other.open(url)
        opened = other.status()
        check(opened["error"] == "", f"the link opened with an error: {opened['error']}")
        check(opened["blocks"] == edited["blocks"],
              f"the blocks differ:\n{opened['blocks']}\n{edited['blocks']}")
        check(opened["method"] == edited["method"], f"the method differs: {opened['method']}")
        check(not opened["unsaved"], "a linked scene opens as unsaved")
        other.wait_frames(2)
        check(not other.errors, "the console has errors:\n" + "\n".join(other.errors))
    finally:
        other.close()
    print(f"a {len(url)}-character link restored {len(edited['blocks'])} blocks exactly and the "
          "method")
    # A damaged fragment: an error that names it; the default scene stays.
    page.open(base + "?scene=newtons_cradle#scene=AAAA-not-deflate")
    s = page.status()
    check("#scene=" in s["error"], f"a damaged link's error does not name the fragment: {s}")
    # A scene too large for a link (40,000 random numbers do not compress below 32,000
    # characters): "Copy link" says so. (gas_500 in motion still fits: 24,000 characters.)
    page.evaluate("sandboxPage.copyLink('', Array.from({length: 40000}, Math.random).join())")
    page.wait(lambda: "too large for a link" in page.status()["error"], "the message")
    print("a damaged fragment is named; a scene too large for a link says so")


def axe_violations(page):
    """axe-core's violations on the page as it is: ["rule: help (n nodes)", ...]."""
    if not page.evaluate("typeof axe !== 'undefined'"):
        page.evaluate(open(AXE_JS, encoding="utf-8").read())
    found = page.evaluate_async(
        "axe.run(document).then(r => JSON.stringify(r.violations.map(v => v.id + ': ' + v.help + "
        "' (' + v.nodes.map(n => n.target.join(' ')).join(', ') + ')')))")
    return json.loads(found)


def axe(page, base):
    page.open(base)
    found = axe_violations(page)
    check(not found, "axe-core at the first frame:\n" + "\n".join(found))
    page.open(base + "?lesson=lecture3&step=5")
    check(page.status()["lessonStep"] == 5, "the lesson did not open")
    page.wait_frames(2)
    check(page.evaluate("document.getElementById('reader-lesson').textContent").startswith(
        "Lesson: "), "the page's text has no lesson")
    found = axe_violations(page)
    check(not found, "axe-core with a lesson open:\n" + "\n".join(found))
    print("axe-core: no violation at the first frame nor with a lesson open")


def live_region(page, base):
    page.open(base + "?scene=lecture_example_1")
    text = lambda id: page.evaluate(f"document.getElementById('{id}').textContent")
    check(text("reader-scene") == "Scene: Lecture example 1", f"scene text: {text('reader-scene')!r}")
    check("paused" in text("reader-status"), f"status text: {text('reader-status')!r}")
    page.evaluate("document.getElementById('c-play').click()")
    page.wait(lambda: page.status()["simTime"] > 0.8, "t = 0.8 s (past the collision)")
    page.wait(lambda: "hits" in text("reader-live"), "the collision in the live region")
    said = text("reader-live")
    for word in ("m1", "m2", "-2", "4"):
        check(word in said, f"the live region lacks {word!r}: {said!r}")
    check(page.evaluate("document.getElementById('reader-live').getAttribute('aria-live')")
          == "polite", "the live region is not polite")
    check("running" in text("reader-status"), f"status text: {text('reader-status')!r}")
    print(f"live region: {said!r}")
    # A change mid-demo that rewords the step's question is said with the question as it now
    # reads (lecture3 step 3 asks with C = 0.5; the page's C control sets 0.9).
    page.open(base + "?lesson=lecture3&step=3")
    check(page.status()["lessonStep"] == 3, "the lesson did not open at step 3")
    page.wait(lambda: "step 3 of" in text("reader-live"), "step 3 said in the live region")
    set_c(page, "0.9")
    page.wait(lambda: "is now 0.90" in text("reader-live"), "the change in the live region")
    said = text("reader-live")
    check("bounciness C is now 0.90; the question now reads: Predict: " in said and
          "C = 0.9" in said, f"the change is not said with the new question: {said!r}")
    print(f"live region after C = 0.9: {said!r}")


def set_c(page, value):
    """Types `value` into the page's hidden C control."""
    page.evaluate("(function () { var c = document.getElementById('c-bounciness'); "
                  f"c.value = '{value}'; c.dispatchEvent(new Event('change', {{bubbles: true}})); }})()")
    page.wait_frames(2)


def hidden_control(page, base):
    page.open(base + "?scene=lecture_example_1")
    check(page.status()["bounciness"] == 1.0, f"C is not 1 at first: {page.status()}")
    set_c = functools.partial(globals()["set_c"], page)
    set_c("0.25")
    check(page.status()["bounciness"] == 0.25, f"the hidden C control did not set C: {page.status()}")
    check(page.evaluate("document.getElementById('c-bounciness').value") == "0.25",
          "the control does not show C")
    set_c("2")
    check(page.status()["bounciness"] == 0.25, "a refused C was taken")
    error = page.evaluate("document.getElementById('c-error').textContent")
    check("must be from 0 to 1" in error, f"the refused C is not said: {error!r}")
    print(f"the hidden C control sets C (0.25); a refused value is said: {error!r}")
    # Every world key of the settings table has a labelled control (page_world_controls.h).
    keys = ["method", "bounciness", "gravity", "dt", "substeps", "resolve", "integrator",
            "mistakes", "drag", "friction"]
    unlabelled = page.evaluate("""[...document.querySelectorAll('#c-world input, #c-world select')]
        .filter(c => !c.labels || c.labels.length === 0).map(c => c.id).join(' ')""")
    check(unlabelled == "", f"controls without a label: {unlabelled}")
    for key in keys:
        check(page.evaluate(f"!!document.getElementById('c-{key}') || "
                            f"!!document.getElementById('c-{key}-x')"), f"no control for {key}")
    page.evaluate("(function () { var c = document.getElementById('c-friction'); c.value = '0.6'; "
                  "c.dispatchEvent(new Event('change', {bubbles: true})); })()")
    page.wait_frames(20)
    check(page.evaluate("document.getElementById('c-error').textContent") == "",
          "the friction control's value was refused")
    check(page.evaluate("document.getElementById('c-friction').value") == "0.6",
          "the friction control does not show the world's friction")
    shown = page.evaluate("document.querySelectorAll('#c-world label').length")
    print(f"{shown} labels; a labelled control for each of {len(keys)} world keys ({', '.join(keys)}); "
          "friction set to 0.6 through its control")


def undo(page, base):
    page.open(base + "?scene=lecture_example_1")
    click = lambda id: (page.evaluate(f"document.getElementById('{id}').click()"),
                        page.wait_frames(2))
    disabled = lambda id: page.evaluate(f"document.getElementById('{id}').disabled")
    check(disabled("c-undo") and disabled("c-redo"), "Undo or Redo enabled with nothing done")
    set_c(page, "0.25")
    # The page's controls follow the app's state at their next refresh (a few frames).
    page.wait(lambda: not disabled("c-undo"), "Undo to be enabled after an edit")
    click("c-undo")
    s = page.status()
    check(s["bounciness"] == 1.0, f"Undo did not take C back: {s}")
    check(s["note"] == "undo: bounciness 0.25 -> 1.00", f"the note: {s['note']!r}")
    page.wait(lambda: not disabled("c-redo"), "Redo to be enabled after an undo")
    click("c-redo")
    check(page.status()["bounciness"] == 0.25, "Redo did not set C again")
    # A block dragged (several moves) is one edit: Ctrl+Z puts it back exactly, Ctrl+Y moves it.
    before = page.status()["blocks"][0]
    block = page.status()["blocksOnScreen"][0]
    x, y = block[0] + block[2] / 2, block[1] + block[3] / 2
    page.drag(x, y, x + 80, y - 40, steps=6)
    moved = page.status()["blocks"][0]
    check(moved[:2] != before[:2], f"the drag did not move the block: {moved}")
    page.evaluate("document.getElementById('canvas').focus()")
    page.key("z", "KeyZ", 90, ctrl=True)
    page.wait_frames(2)
    check(page.status()["blocks"][0][:2] == before[:2],
          f"Ctrl+Z did not put the block back: {page.status()['blocks'][0]} != {before}")
    page.key("y", "KeyY", 89, ctrl=True)
    page.wait_frames(2)
    check(page.status()["blocks"][0][:2] == moved[:2], "Ctrl+Y did not move it again")
    page.key("z", "KeyZ", 90, ctrl=True)
    page.key("z", "KeyZ", 90, ctrl=True)
    page.wait_frames(2)
    check(page.status()["bounciness"] == 1.0, "two Ctrl+Z did not take back the drag and C")
    print(f"Undo and Redo set C back and again; a drag is one edit ({page.status()['note']!r})")


def sound(page, base):
    page.open(base + "?scene=lecture_example_1")
    played = ("typeof AL !== 'undefined' && AL.currentCtx ? Object.values(AL.currentCtx.sources)"
              ".filter(s => s && s.state !== 0x1011 /* AL_INITIAL */).length : -1")
    check(page.evaluate(played) == -1, "a sound context before any sound")
    page.key("m", "KeyM", 77)
    page.key("p", "KeyP", 80)
    page.wait(lambda: page.status()["simTime"] > 0.8, "t = 0.8 s (past the collision)")
    page.wait(lambda: page.evaluate(played) > 0, "a knock played")
    state = page.evaluate("AL.currentCtx.audioCtx.state")
    print(f"M and the collision: {page.evaluate(played)} OpenAL source(s) played; "
          f"Web Audio context {state}")


FOCUS_RING = (255, 217, 64)  # ui_style.cpp's NavHighlight, dark theme


def focus_ring_shown(img, rect):
    """Pixels of the focus ring's colour on the outline of `rect` (grown by 4 px)."""
    x0, y0, x1, y1 = rect[0] - 4, rect[1] - 4, rect[2] + 4, rect[3] + 4
    near = lambda p: all(abs(a - b) <= 40 for a, b in zip(p, FOCUS_RING))
    count = 0
    for x in range(max(0, x0), min(img.width, x1)):
        for y in range(max(0, y0), min(img.height, y1)):
            if (x - x0 < 8 or x1 - x < 8 or y - y0 < 8 or y1 - y < 8) and near(img.getpixel((x, y))):
                count += 1
    return count


def keyboard(page, base):
    page.open(base)
    page.key("F6", "F6", 117)
    page.wait_frames(3)
    s = page.status()
    check(s["navVisible"], f"F6 did not show the focus ring: {s}")
    seen, unringed = {}, []
    for _ in range(40):
        s = page.status()
        if s["navVisible"] and s["navId"] not in seen:
            img = image(page.screenshot())
            seen[s["navId"]] = s["navRect"]
            if focus_ring_shown(img, s["navRect"]) < 20:
                unringed.append(s["navRect"])
            if len(seen) == 15:
                img.save(FOCUS_SHOT)
        if len(seen) >= 20:
            break
        page.key("ArrowDown", "ArrowDown", 40)
        page.wait_frames(2)
    check(len(seen) >= 15, f"the arrows reached only {len(seen)} controls")
    check(not unringed, f"no focus ring seen around {unringed}")
    print(f"F6 and the arrows walked through {len(seen)} controls, each with its focus ring "
          f"({FOCUS_SHOT}: the 15th)")


def keys(page, base):
    page.open(base + "?lesson=lecture3")
    page.wait_frames(3)
    page.evaluate("Module._sandbox_web_verbose(1)")
    canvas_focused = "document.activeElement === canvas"
    check(page.evaluate(canvas_focused), "the canvas does not have the focus at first")

    def press(key, code, key_code, want, shift=False, kinds=("keyDown", "keyUp"), text=None):
        """The key, then each line of `want` (regular expressions) in the log; then 10 frames for
        anything else it would do. Returns the lines it caused."""
        start = len(page.logs)
        page.key(key, code, key_code, shift=shift, kinds=kinds, text=text)
        for w in want:
            def seen():
                page.status()  # the console's lines arrive with the page's answers
                return any(re.search(w, line) for line in page.logs[start:])
            page.wait(seen, f"{w!r} in the log after {key} (log: {page.logs[start:]})")
        page.wait_frames(10)
        page.status()
        return page.logs[start:]

    def only(said, *patterns):
        for line in said:
            check(any(re.search(p, line) for p in patterns), f"unexpected {line!r} in {said}")

    def lecture_keys_only(said):
        for bad in ("keyboard navigation", "^keyboard:", "^mistakes"):
            check(not any(re.search(bad, line) for line in said), f"{bad!r} in {said}")
        s = page.status()
        check(not s["navVisible"] and s["keyboardWindow"] == "", f"a focus ring or a window "
              f"has the keyboard: {s['navVisible']}, {s['keyboardWindow']!r}")

    # The panel's C slider: a click sets C and leaves the keyboard to the scene.
    slider = page.status()["bouncinessSlider"]
    y = slider[1] + slider[3] / 2

    def click_slider(x, ctrl=False):
        control = dict(key="Control", code="ControlLeft", windowsVirtualKeyCode=17,
                       nativeVirtualKeyCode=17)
        if ctrl:
            page.call("Input.dispatchKeyEvent", type="rawKeyDown", modifiers=2, **control)
        page.mouse("mouseMoved", x, y)
        page.wait_frames(1)
        page.mouse("mousePressed", x, y, buttons=1, modifiers=2 if ctrl else 0)
        page.wait_frames(2)
        page.mouse("mouseReleased", x, y, modifiers=2 if ctrl else 0)
        page.wait_frames(2)
        if ctrl:
            page.call("Input.dispatchKeyEvent", type="keyUp", **control)
        page.mouse("mouseMoved", 1270, 715)  # the pointer off the panel (no tooltip)
        page.wait_frames(2)

    def type_into_slider(*digits):
        """A Ctrl+click on the slider (a text field, all selected), then the digits, each the
        field's ("key N: typing")."""
        click_slider(slider[0] + slider[2] / 4, ctrl=True)
        page.wait(lambda: page.status()["typing"], "the Ctrl+click to open the slider for typing")
        said = []
        for d in digits:
            if d == ".":
                said += press(".", "Period", 190, [], text=".")
            else:
                said += press(d, f"Digit{d}", 48 + int(d), [rf"^key {d}: typing$"], text=d)
        for bad in ("lesson-digit", "lesson step typed"):
            check(not any(bad in line for line in said), f"{bad!r} while typing: {said}")
        return said

    # (The slider's rectangle holds its label too: 0.3 of it is about the middle of its bar.)
    start = len(page.logs)
    was = page.status()["bounciness"]
    click_slider(slider[0] + slider[2] * 0.3)
    s = page.status()
    check(0.2 <= s["bounciness"] <= 0.7 and s["bounciness"] != was,
          f"the click on the C slider: C = {s['bounciness']} (was {was})")
    lecture_keys_only(page.logs[start:])
    type_into_slider("0", ".", "7")
    said = press("Enter", "Enter", 13, [r"^key Enter: typing$"])
    check(not any("lesson-jump" in line for line in said), f"Enter: {said}")
    s = page.status()
    check(abs(s["bounciness"] - 0.7) < 1e-6 and not s["typing"],
          f"typed 0.7 and Enter: C = {s['bounciness']}, typing {s['typing']}")
    lecture_keys_only(said)
    type_into_slider("0", ".", "3")
    # Esc undoes the typing: C is 0.7 again (an edit line says so when the typing had changed it).
    said = press("Escape", "Escape", 27, [r"^key Esc: escape$", r"^escape: the field left$"])
    only(said, r"^key Esc: escape$", r"^escape: the field left$", r"^bounciness: 0.7$")
    check(not page.status()["typing"], "Esc did not leave the field")
    check(page.status()["bounciness"] == 0.7, f"Esc left C at {page.status()['bounciness']}")
    type_into_slider("0", ".", "6")
    said = press("F5", "F5", 116, [r"^key F5: present$", r"^present mode: on$"])
    only(said, r"^key F5: present$", r"^present mode: on$", r"^bounciness: 0.6$")
    press("F5", "F5", 116, [r"^present mode: off$"])
    check(not page.status()["typing"], "F5 did not leave the field")
    type_into_slider("0", ".", "8")
    said = press("PageDown", "PageDown", 34, [r"^key PageDown: lesson-next$", r"^resumed$",
                                              r"^paused$"])  # its moment, by itself (2.5 s)
    lecture_keys_only(said)
    check(abs(page.status()["bounciness"] - 0.8) < 1e-6, "the field's 8 was lost")
    print("the C slider clicked, then typed into: the digits and Enter went to the field, Esc "
          "undid the typing, F5 and PageDown acted and left the field")

    # Right three times, the slider the last control worked: step 2, it plays, then its moment
    # (Right while it runs) or step 3 (when it has paused there by itself already).
    lecture_keys_only(press("ArrowRight", "ArrowRight", 39, [r"^key Right: lesson-next$",
                                                                r"^lesson step 2 / 27 "]))
    lecture_keys_only(press("ArrowRight", "ArrowRight", 39, [r"^key Right: lesson-next$",
                                                                r"^resumed$"]))
    lecture_keys_only(press("ArrowRight", "ArrowRight", 39, [r"^key Right: lesson-next$",
                                                                r"^(paused|lesson step 3 / 27 .*)$"]))
    said = press(" ", "Space", 32, [r"^key Space: slow-motion$", r"^slow motion: on$"])
    only(said, r"^key Space: slow-motion$", r"^slow motion: on$")
    lecture_keys_only(said)
    press("1", "Digit1", 49, [r"^key 1: lesson-digit$"])
    press("3", "Digit3", 51, [r"^key 3: lesson-digit$", r"^lesson step typed: 13$"])
    lecture_keys_only(press("Enter", "Enter", 13, [r"^key Enter: lesson-jump$",
                                                     r"^lesson step 13 / 27 "]))
    check(page.status()["lessonStep"] == 13, f"1 3 Enter: step {page.status()['lessonStep']}")
    said = press("s", "KeyS", 83, [r"^key S: cycle-method$", r"^method: move-and-correct$"])
    only(said, r"^key S: cycle-method$", r"^method: move-and-correct$")
    said = press("R", "KeyR", 82, [r"^key Shift\+R: reset-to-file$",
                                   r"^lesson step as written 13$", r"^method: perfect$"],
                 shift=True)
    lecture_keys_only(said)
    print("Right x3, Space, 1 3 Enter, S and Shift+R did what the key table says, and nothing "
          "else (no focus ring, the keyboard the scene's)")

    # F5: present mode, never a reload. Headless Chromium reloads on no synthetic F5 (tried: not
    # even on a form control), so what is checked is what stops a browser's reload: the key
    # event's default is prevented (seen by a listener after the page's), and the page is still
    # the same page.
    page.evaluate("window.sandboxNotReloaded = true; window.addEventListener('keydown', e => { "
                  "if (e.key === 'F5') window.sandboxF5Prevented = e.defaultPrevented; })")
    said = press("F5", "F5", 116, [r"^key F5: present$", r"^present mode: on$"])
    only(said, r"^key F5: present$", r"^present mode: on$")
    check(page.evaluate("window.sandboxF5Prevented") is True, "F5's default (reload) was not "
          f"prevented: {page.evaluate('window.sandboxF5Prevented')}")
    check(page.evaluate("window.sandboxNotReloaded === true"), "F5 reloaded the page")
    check(page.status()["presentMode"], "F5: not in present mode")
    press("F5", "F5", 116, [r"^present mode: off$"])
    check(page.evaluate("window.sandboxNotReloaded === true"), "F5 reloaded the page")
    print("F5 toggled present mode twice; its default (a reload) was prevented, the page stayed")

    # F6: the panel has the keyboard (its ring shows); Down moves the ring; Esc gives it back.
    press("F6", "F6", 117, [r"^keyboard: Controls$"])
    page.wait_frames(3)
    check(page.status()["navVisible"], "F6 showed no focus ring")
    said = press("ArrowDown", "ArrowDown", 40, [r"^key Down: keyboard navigation$"])
    check(not any(line.startswith("lesson step") for line in said), f"Down: {said}")
    press("Escape", "Escape", 27, [r"^keyboard: scene$"])
    check(not page.status()["navVisible"], "the focus ring stays after Esc")
    print("F6 gave the panel the keyboard with its ring, Esc gave it back")

    # Tab leaves the canvas for the page's first control (the app sees no Tab); Shift+Tab comes
    # back, and the keys are the sandbox's again.
    start = len(page.logs)
    page.key("Tab", "Tab", 9)
    page.wait(lambda: page.evaluate("document.activeElement.id") == "c-scene",
              "Tab to move the focus to the page's scene control")
    page.wait_frames(5)
    page.status()
    check(not any(line.startswith("key Tab") for line in page.logs[start:]),
          f"the app saw the Tab: {page.logs[start:]}")
    check(page.status()["keyboardWindow"] == "", "Tab gave a window the keyboard")
    page.key("Tab", "Tab", 9, shift=True)
    page.wait(lambda: page.evaluate(canvas_focused), "Shift+Tab to come back to the canvas")
    lecture_keys_only(press("ArrowRight", "ArrowRight", 39, [r"^key Right: lesson-next$"]))
    print("Tab left the canvas for the page's controls (the app saw no Tab); Shift+Tab came back")

    # Step 26 plays its player's keys itself: Left (which it never presses) takes the player.
    press("2", "Digit2", 50, [r"^key 2: lesson-digit$"])
    press("6", "Digit6", 54, [r"^key 6: lesson-digit$"])
    press("Enter", "Enter", 13, [r"^lesson step 26 / 27 "])
    press("PageDown", "PageDown", 34, [r"^key PageDown: lesson-next$", r"^resumed$"])
    said = press("ArrowLeft", "ArrowLeft", 37, [r"^key Left: thrust-left$",
                                               r"^player: the arrow keys drive it",
                                               r"^player keys: left$"], kinds=("keyDown",))
    said += press("ArrowLeft", "ArrowLeft", 37, [r"^player keys: none$"], kinds=("keyUp",))
    check(not any(line.startswith("lesson step") for line in said), f"Left stepped: {said}")
    check(page.status()["lessonStep"] == 26, "the arrows stepped the lesson")
    print("on step 26 Left drove the player (the step's own input stopped)")


def phone(base):
    page = Page(390, 844, 3, touch=True)
    try:
        page.open(base)
        page.wait_frames(2)
        s = page.status()
        check(s["sheet"] and not s["sheetOpen"], f"not a closed sheet: {s['panelOnScreen']}")
        scene = s["sceneOnScreen"]
        share = scene[2] * scene[3] / (390 * 844)
        check(share >= 0.6, f"the scene has {share:.0%} of the screen")
        # The first view shows the whole scene: the world's bounds inside the scene's rectangle
        # (to 0.5 CSS px, rounding), so every block is in view. (Blocks of 24 CSS px cannot be
        # had too: the default scene is 20 m wide and its smallest block 0.6 m, at most
        # 390 / 20 x 0.6 = 11.7 CSS px; the whole scene comes first.)
        world = s["worldOnScreen"]
        inside = lambda r: (r[0] >= scene[0] - 0.5 and r[1] >= scene[1] - 0.5 and
                            r[0] + r[2] <= scene[0] + scene[2] + 0.5 and
                            r[1] + r[3] <= scene[1] + scene[3] + 0.5)
        check(inside(world), f"the world {world} is not all inside the scene {scene}")
        check(all(inside(b) for b in s["blocksOnScreen"]), f"a block out of view: {s}")
        smallest = min(min(b[2], b[3]) for b in s["blocksOnScreen"])
        # The hint: shown, inside the screen with its buttons (each inside it, 44 px high).
        hint = page.evaluate("(() => { const h = document.getElementById('hint'); "
                             "const r = h.getBoundingClientRect(); "
                             "const b = [...h.querySelectorAll('button')].map("
                             "e => e.getBoundingClientRect()); return [!h.hidden, r.left, r.right, "
                             "Math.min(...b.map(e => e.height)), Math.min(...b.map(e => e.left)), "
                             "Math.max(...b.map(e => e.right))]; })()")
        check(hint[0] and 0 <= hint[1] and hint[2] <= 390 and hint[3] >= 44 and
              hint[1] <= hint[4] and hint[5] <= hint[2], f"the first visit's hint: {hint}")
        # A phone has no F1: the hint names only the button (innerText leaves hidden text out).
        words = page.evaluate("document.getElementById('hint').innerText")
        check("F1" not in words and "Help" in words, f"the phone's hint says {words!r}")
        panel = s["panelOnScreen"]
        page.tap(panel[0] + 40, panel[1] + panel[3] / 2)  # "Controls", the bar's first button
        s = page.status()
        check(s["sheetOpen"], "a tap on Controls did not open the sheet")
        check(page.evaluate("document.getElementById('hint').hidden"),
              "the hint stays over the open sheet")
        check(s["touchUi"] and s["frameHeight"] >= 44, f"controls {s['frameHeight']} px high")
        check(not s["pointerOnScreen"], "the pointer stays after a tap (a tooltip would too)")
        slider = s["bouncinessSlider"]
        x, y = slider[0] + slider[2] * 0.3, slider[1] + slider[3] / 2
        settings = (s["bounciness"], s["gravity"], s["method"])
        page.swipe(x, y, x, y - 80)  # the slider stays in view
        s = page.status()
        moved = slider[1] - s["bouncinessSlider"][1]
        check(abs(moved - 80) < 1, f"the panel scrolled by {moved} px (the swipe: 80)")
        check((s["bounciness"], s["gravity"], s["method"]) == settings,
              f"the swipe changed a setting: {settings} -> {s['bounciness'], s['gravity']}")
        check(not s["pointerOnScreen"], "the pointer stays after a swipe")
        slider = s["bouncinessSlider"]
        page.tap(slider[0] + slider[2] * 0.3, slider[1] + slider[3] / 2)
        page.wait(lambda: page.evaluate("document.activeElement.id") == "type-in",
                  "the on-screen keyboard's field to take the focus")
        check(page.status()["typing"], "the slider did not open for typing")
        page.call("Input.insertText", text="0.5")
        page.key("Enter", "Enter", 13)
        page.wait_frames(3)
        s = page.status()
        check(s["bounciness"] == 0.5, f"typed 0.5, the bounciness is {s['bounciness']}")
        check(page.evaluate("document.activeElement.id") != "type-in", "the keyboard stays")
        panel = s["panelOnScreen"]
        page.tap(panel[0] + 40, panel[1] + 30)  # "Close"
        check(not page.status()["sheetOpen"], "a tap on Close did not close the sheet")
        page.wait_frames(2)
        check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
        print(f"390x844: the scene {share:.0%} of the screen, the whole world in view "
              f"({world[2]:.0f}x{world[3]:.0f} CSS px), blocks >= {smallest:.1f} CSS px, "
              f"controls {s['frameHeight']:.0f} px; the sheet opens and closes, a swipe scrolled "
              f"it by {moved:.0f} px and changed nothing; 0.5 typed into C")
    finally:
        page.close()


def offline(site, base):
    one_file = "file://" + os.path.abspath(os.path.join(site, "sandbox-offline.html"))
    folder = "file://" + os.path.abspath(os.path.join(site, "index.html"))
    # One Chromium for both parts (CI time): the file:// pages leave nothing for the served
    # origin (its own server, a port of its own), which the second part visits first.
    page = Page(1280, 720)
    try:
        page.open(one_file)
        img = image(page.screenshot())
        colours = colour_count(img)
        check(colours >= 300, f"the one-file build's first frame has only {colours} colours")
        s = page.status()
        check(s["scene"].endswith("/bouncing_squares.json") and s["error"] == "", f"{s}")
        page.call("Page.navigate", url=folder)
        page.wait(lambda: "sandbox-offline.html" in page.evaluate(
            "document.getElementById('note') ? document.getElementById('note').textContent : ''"),
            "the folder build's note about file://")
        check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
        print(f"file://: the one-file build drew the default scene ({colours} colours); the "
              "folder build says what to do")
        # Served, visited once, then the server goes away: the service worker's copy answers.
        server, base = serve(site)
        url = base + "?scene=newtons_cradle"
        page.open(url)
        page.evaluate("navigator.serviceWorker.ready.then(() => { window.sandboxWorker = 1; })")
        page.wait(lambda: page.evaluate("!!window.sandboxWorker"), "the service worker")
        page.wait(lambda: page.evaluate("caches.open('collision-sandbox').then(c => c.keys())"
                                        ".then(k => window.sandboxKept = k.length), "
                                        "window.sandboxKept >= 5"), "the files to be kept")
        server.shutdown()
        server.server_close()
        page.reload()
        s = page.status()
        check(s["scene"].endswith("/newtons_cradle.json"), f"offline: {s}")
    finally:
        page.close()
    print("served: once visited, the page opened again with the server gone")


def shots(base, out_dir):
    """Screenshots to look at (docs/web/): a phone held upright (the sheet closed, then open), a
    tablet, a laptop, and the projector cases."""
    os.makedirs(out_dir, exist_ok=True)
    every = "?show=plots,inspector,com,poi,timeline,vectors,trails,sidebyside,cost"
    # (name, CSS width, height, device pixel ratio, touch, query, open the sheet): the 1080p
    # projector is also seen as a 1280x720 page at ratio 1.5 (the window's --ui-scale 1.5).
    cases = (("phone_390x844", 390, 844, 3, True, "", False),
             ("phone_390x844_panel", 390, 844, 3, True, "", True),
             ("tablet_1024x768", 1024, 768, 2, True, "", False),
             ("laptop_1366x768", 1366, 768, 1, False, "", False),
             ("web_1280x720", 1280, 720, 1, False, "", False),
             ("web_1920x1080_every_overlay", 1920, 1080, 1, False, every, False),
             ("web_1280x720_ratio1.5_every_overlay", 1280, 720, 1.5, False, every, False))
    for name, w, h, ratio, touch, query, sheet in cases:
        page = Page(w, h, ratio, touch)
        try:
            page.open(base + query)
            page.wait_frames(30)
            if sheet:
                panel = page.status()["panelOnScreen"]
                page.tap(panel[0] + 40, panel[1] + panel[3] / 2)
                page.wait_frames(5)
            path = os.path.join(out_dir, name + ".png")
            open(path, "wb").write(page.screenshot())
            print(path, f"(first frame after {page.evaluate('window.sandboxFirstFrame'):.0f} ms)")
            check(not page.errors, "\n".join(page.errors))
        finally:
            page.close()


def run_site(site, run):
    """The browser tests' shared main: skipped where Chromium or the built site is missing, else
    `site` served on 127.0.0.1 and run(base) called with its URL; prints "passed" or the failed
    check and returns the exit code (browser_test.py, big_inputs_test.py)."""
    if not os.path.exists(CHROMIUM):
        skip("chromium is not installed (scripts/web.sh deps installs it)")
    if not os.path.exists(os.path.join(site, "index.html")):
        skip(f"{site}/index.html is missing: build the browser build with scripts/web.sh build")
    server, base = serve(site)
    try:
        run(base)
    except AssertionError as e:
        print(f"FAILED: {e}")
        return 1
    finally:
        server.shutdown()
    print("passed")
    return 0


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    site, what = sys.argv[1], sys.argv[2]
    if what == "axe" and not os.path.exists(AXE_JS):
        skip(f"{AXE_JS} is missing (scripts/web.sh deps installs axe-core)")
    checks = {"first-frame": first_frame, "pause": pause, "url-scene": url_scene,
              "url-lesson": url_lesson, "url-bad": url_bad, "open-file": open_file,
              "wheel": wheel, "trackers": trackers, "unsaved": unsaved, "link": link,
              "axe": axe, "live-region": live_region, "hidden-control": hidden_control,
              "undo": undo,
              "keyboard": keyboard, "keys": keys, "sound": sound}

    def run(base):
        if what == "shots":
            shots(base, sys.argv[3])
        elif what == "fullscreen":
            for ratio in (1, 2):
                fullscreen(base, ratio)
        elif what in ("phone", "offline"):
            phone(base) if what == "phone" else offline(site, base)
        else:
            page = Page(1280, 720)
            try:
                checks[what](page, base)
                page.wait_frames(2)  # let late messages arrive
                check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
            finally:
                page.close()

    return run_site(site, run)


if __name__ == "__main__":
    sys.exit(main())
