#!/usr/bin/python3
"""The browser build in a real browser: headless Chromium (Debian's chromium, WebGL 2 on the CPU
through SwiftShader) opens build-web/index.html from a local server and is driven over the
DevTools protocol (python3-websocket). One check per run:

  first-frame   the first frame draws the default scene: a screenshot with many colours, the
                controls panel visible, the default scene loaded
  pause         P pauses: two screenshots taken frames apart are equal (and were not before)
  url-scene     ?scene=newtons_cradle&method=turn-based&show=plots,inspector selects them
  url-lesson    ?lesson=lecture3&step=5 opens the lesson at step 5
  url-bad       bad URL parameters show their errors in the panel and keep the default scene
  open-file     a picked or dropped file opens; a bad one shows its error (with its place) and
                keeps the current scene
  axe           axe-core (npm, injected into the page) finds no violation at the first frame
                and with a lesson open
  live-region   lecture_example_1 played (with the page's own Play button) through its
                collision leaves the live region saying it in the inspector's words; the page's
                text names the scene and the lesson's step
  hidden-control  the page's hidden C control sets the world's C; a refused value is said
  sound         M turns the sound on and lecture_example_1's collision plays a knock through
                emscripten's OpenAL (a source of its Web Audio context has played)
  keyboard      Tab, then the arrow keys, walk through at least 15 of the panel's controls, each
                with the focus ring shown around it (keyboard_focus.png is written for looking)
  shots DIR     writes 1280x720 and 1920x1080 screenshots into DIR (for looking at)

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
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

SKIP = 77
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


class Page:
    """One Chromium with one page, over the DevTools protocol."""

    def __init__(self, width, height, pixel_ratio=1.0):
        self.profile = tempfile.mkdtemp(prefix="sandbox-chromium-")
        self.proc = subprocess.Popen(
            [CHROMIUM, "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--no-first-run", "--no-default-browser-check",
             "--disable-extensions", "--hide-scrollbars", "--mute-audio",
             f"--window-size={width},{height}", f"--force-device-scale-factor={pixel_ratio}",
             "--remote-debugging-port=0",
             f"--user-data-dir={self.profile}", "about:blank"],
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
        self.call("Runtime.enable")
        self.call("Log.enable")
        self.call("Page.enable")
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
                  deviceScaleFactor=pixel_ratio, mobile=False)

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

    def key(self, key, code, key_code):
        for kind in ("keyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=code,
                      windowsVirtualKeyCode=key_code, nativeVirtualKeyCode=key_code)


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
    check("URL parameter method: unknown method 'fastest'" in s["error"], f"no method error: {s}")
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


def hidden_control(page, base):
    page.open(base + "?scene=lecture_example_1")
    check(page.status()["bounciness"] == 1.0, f"C is not 1 at first: {page.status()}")

    def set_c(value):
        page.evaluate("(function () { var c = document.getElementById('c-bounciness'); "
                      f"c.value = '{value}'; c.dispatchEvent(new Event('change', {{bubbles: true}})); }})()")
        page.wait_frames(2)

    set_c("0.25")
    check(page.status()["bounciness"] == 0.25, f"the hidden C control did not set C: {page.status()}")
    check(page.evaluate("document.getElementById('c-bounciness').value") == "0.25",
          "the control does not show C")
    set_c("2")
    check(page.status()["bounciness"] == 0.25, "a refused C was taken")
    error = page.evaluate("document.getElementById('c-error').textContent")
    check("must be from 0 to 1" in error, f"the refused C is not said: {error!r}")
    print(f"the hidden C control sets C (0.25); a refused value is said: {error!r}")


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
    page.key("Tab", "Tab", 9)
    page.wait_frames(3)
    s = page.status()
    check(s["navVisible"], f"Tab did not show the focus ring: {s}")
    seen, unringed = {}, []
    for _ in range(40):
        s = page.status()
        if s["navVisible"] and s["navId"] not in seen:
            img = image(page.screenshot())
            seen[s["navId"]] = s["navRect"]
            if focus_ring_shown(img, s["navRect"]) < 20:
                unringed.append(s["navRect"])
            if len(seen) == 15:
                img.save("keyboard_focus.png")
        if len(seen) >= 20:
            break
        page.key("ArrowDown", "ArrowDown", 40)
        page.wait_frames(2)
    check(len(seen) >= 15, f"the arrows reached only {len(seen)} controls")
    check(not unringed, f"no focus ring seen around {unringed}")
    print(f"Tab and the arrows walked through {len(seen)} controls, each with its focus ring "
          f"(keyboard_focus.png: the 15th)")


def shots(base, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    every = "?show=plots,inspector,com,poi,timeline,vectors,trails,sidebyside,cost"
    # (CSS width, height, device pixel ratio, query): the last is a 1080p projector seen as a
    # 1280x720 page at ratio 1.5, so the UI scale is 1.5 as the window's --ui-scale 1.5.
    for w, h, ratio, query in ((1280, 720, 1, ""), (1920, 1080, 1, every), (1280, 720, 1.5, every)):
        page = Page(w, h, ratio)
        try:
            page.open(base + query)
            page.wait_frames(30)
            path = os.path.join(out_dir, f"web_{w}x{h}_ratio{ratio}.png")
            open(path, "wb").write(page.screenshot())
            print(path, f"(first frame after {page.evaluate('window.sandboxFirstFrame'):.0f} ms)")
            check(not page.errors, "\n".join(page.errors))
        finally:
            page.close()


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    site, what = sys.argv[1], sys.argv[2]
    if not os.path.exists(CHROMIUM):
        skip("chromium is not installed (scripts/web.sh deps installs it)")
    if what == "axe" and not os.path.exists(AXE_JS):
        skip(f"{AXE_JS} is missing (scripts/web.sh deps installs axe-core)")
    if not os.path.exists(os.path.join(site, "index.html")):
        skip(f"{site}/index.html is missing: build the browser build with scripts/web.sh build")
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(QuietHandler, directory=site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/index.html"
    checks = {"first-frame": first_frame, "pause": pause, "url-scene": url_scene,
              "url-lesson": url_lesson, "url-bad": url_bad, "open-file": open_file, "axe": axe,
              "live-region": live_region, "hidden-control": hidden_control, "keyboard": keyboard,
              "sound": sound}
    try:
        if what == "shots":
            shots(base, sys.argv[3])
            return 0
        page = Page(1280, 720)
        try:
            checks[what](page, base)
            page.wait_frames(2)  # let late messages arrive
            check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
        finally:
            page.close()
    except AssertionError as e:
        print(f"FAILED: {e}")
        return 1
    finally:
        server.shutdown()
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
