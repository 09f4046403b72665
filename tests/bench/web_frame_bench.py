#!/usr/bin/python3
"""The browser build's cost, measured in headless Chromium (a benchmark: reported, never a test).

  tests/bench/web_frame_bench.py SITE [SITE ...] [--rounds N]

For each SITE (a build-web/ folder; give the before and the after build to compare them in one
sitting, taken in turns), at 1280x720 and ratio 1:
  - the app's JavaScript per frame: the time inside the page's requestAnimationFrame callbacks
    (emscripten's main loop: the app's frame, its WebGL calls, the UI), median over 120 frames
    after 30 to warm up, the simulation running, for the default scene, gas_500, and the default
    scene with every overlay on;
  - the first frame: ms from the start of loading to the first frame shown (the page's
    window.sandboxFirstFrame), on a warm server and cache (the page loaded once before).
Each figure is the median over the rounds (default 3). The machine's load matters: report
`uptime` with the figures.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "web"))
import browser_test  # noqa: E402  (its Page drives Chromium over the DevTools protocol)

EVERY = "show=plots,inspector,com,poi,timeline,vectors,trails,sidebyside,velocityspace,cost"
CASES = (("default scene", ""), ("gas_500", "scene=gas_500"), ("every overlay", EVERY))
WARM_FRAMES, FRAMES = 30, 120

# Times every requestAnimationFrame callback (installed before the page's scripts run).
TIMER = """
(() => {
  const raf = window.requestAnimationFrame.bind(window);
  window.sandboxFrameMs = [];
  window.requestAnimationFrame = (callback) => raf((t) => {
    const t0 = performance.now();
    callback(t);
    window.sandboxFrameMs.push(performance.now() - t0);
  });
})();
"""


def serve(site):
    server = browser_test.http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0),
        browser_test.functools.partial(browser_test.QuietHandler, directory=site))
    browser_test.threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/index.html"


def frame_ms(base, query):
    page = browser_test.Page(1280, 720)
    try:
        page.call("Page.addScriptToEvaluateOnNewDocument", source=TIMER)
        page.open(base + ("?" + query if query else ""))
        if page.status()["paused"]:
            page.key("p", "KeyP", 80)
        page.wait(lambda: not page.status()["paused"], "the simulation to run")
        count = "window.sandboxFrameMs.length"
        start = page.evaluate(count)
        page.wait(lambda: page.evaluate(count) >= start + WARM_FRAMES, "warm-up frames")
        start = page.evaluate(count)
        page.wait(lambda: page.evaluate(count) >= start + FRAMES, "the measured frames")
        times = page.evaluate(f"window.sandboxFrameMs.slice({start}, {start + FRAMES})")
        return statistics.median(times)
    finally:
        page.close()


def first_frame_ms(base):
    page = browser_test.Page(1280, 720)
    try:
        page.open(base)  # the cold load fills the cache; the reload is the warm one
        page.reload()
        return page.evaluate("window.sandboxFirstFrame")
    finally:
        page.close()


def main():
    args = sys.argv[1:]
    rounds = 3
    if "--rounds" in args:
        at = args.index("--rounds")
        rounds = int(args[at + 1])
        del args[at:at + 2]
    if not args:
        print(__doc__)
        return 2
    servers = {site: serve(site) for site in args}
    results = {site: {name: [] for name, _ in CASES + (("first frame", None),)} for site in args}
    for r in range(rounds):
        for site in args:  # in turns, so that the load changes both alike
            base = servers[site][1]
            for name, query in CASES:
                results[site][name].append(frame_ms(base, query))
            results[site]["first frame"].append(first_frame_ms(base))
            print(f"round {r + 1}/{rounds}: {site}: " + ", ".join(
                f"{k} {v[-1]:.2f} ms" for k, v in results[site].items()), flush=True)
    print(f"\nmedians of {rounds} rounds (per frame: the median of {FRAMES} frames), 1280x720:")
    for site in args:
        print(f"  {site}: " + ", ".join(
            f"{k} {statistics.median(v):.2f} ms" for k, v in results[site].items()))
    for server, _ in servers.values():
        server.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
