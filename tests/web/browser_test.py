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
                keeps the current scene; a student's trace (.csv) opens at its first difference
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

    # A student's trace (a .csv, docs/compare.md) opens on the current scene: point_of_impact's
    # mover as the reference moves it for four frames, then left unresolved in the fifth.
    s = pick("point_of_impact.json", "FS.readFile('/scenes/point_of_impact.json')")
    check(s["error"] == "" and s["traceFirstDifference"] is None, f"no scene or a trace: {s}")
    rows = ["t,mover_x,mover_y,mover_vx,mover_vy"]
    for k in range(1, 6):  # dt 0.1 s, velocity (14, -14) m/s from (3, 9.5)
        rows.append(f"{k / 10:g},{3 + 1.4 * k:g},{9.5 - 1.4 * k:g},14,-14")
    s = pick("my_trace.csv", json.dumps("\n".join(rows) + "\n"))
    check(s["error"] == "", f"error after a good trace: {s}")
    check(s["traceFirstDifference"] == 5, f"the first difference is not frame 5: {s}")
    check(s["paused"] and s["simTime"] > 0.45, f"the run did not stop at the difference: {s}")
    s = pick("bad_trace.csv", json.dumps("t,mover_x,mover_y,mover_vx,mover_vy\n0.1,abc,8.1,14,-14\n"))
    check("bad_trace.csv:2:5" in s["error"] and "mover_x" in s["error"], f"no place: {s}")
    check(s["traceFirstDifference"] == 5, f"a bad trace replaced the open one: {s}")
    print("a trace opens on the scene at its first difference; a bad one shows its place")


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
    if not os.path.exists(os.path.join(site, "index.html")):
        skip(f"{site}/index.html is missing: build the browser build with scripts/web.sh build")
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(QuietHandler, directory=site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/index.html"
    checks = {"first-frame": first_frame, "pause": pause, "url-scene": url_scene,
              "url-lesson": url_lesson, "url-bad": url_bad, "open-file": open_file}
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
