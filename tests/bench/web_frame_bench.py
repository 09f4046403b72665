#!/usr/bin/python3
"""The browser build's cost, measured in headless Chromium (a benchmark: reported, never a test).

  tests/bench/web_frame_bench.py SITE [SITE ...] [--rounds N]

For each SITE (a build-web/ folder; give the before and the after build to compare them in one
sitting, taken in turns), at 1280x720:
  - the app's JavaScript per frame: the time inside the page's requestAnimationFrame callbacks
    (emscripten's main loop: the app's frame, its WebGL calls, the UI), median and 95th
    percentile over 120 frames after 30 to warm up, the simulation running, at device pixel
    ratio 1 for the default scene, gas_500, the default scene with every overlay on and gas_500
    with every overlay on, and at ratio 2 for the default scene with every overlay on;
  - the first frame: ms from the start of loading to the first frame shown (the page's
    window.sandboxFirstFrame), on a warm server and cache (the page loaded once before).
Each figure is the median over the rounds (default 3); each SITE after the first also has its
medians given as a share of the first's. `--only TEXT` takes only the cases whose names hold TEXT
(and no first frame). The machine's load matters: the load average is printed at the start and
the end; report it with the figures.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "web"))
import browser_test  # noqa: E402  (its Page drives Chromium over the DevTools protocol)

EVERY = "show=plots,inspector,com,poi,timeline,vectors,trails,sidebyside,velocityspace,cost"
# (name, URL parameters, device pixel ratio)
CASES = (("default scene", "", 1), ("gas_500", "scene=gas_500", 1), ("every overlay", EVERY, 1),
         ("gas_500 every overlay", "scene=gas_500&" + EVERY, 1),
         ("every overlay ratio 2", EVERY, 2))
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


serve = browser_test.serve  # web_profile.py calls it here


def percentile(values, share):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(share * len(ordered)))]


FRAME_COUNT = "window.sandboxFrameMs.length"


def open_running(page, base, query, warm_frames, scripts=()):
    """Opens the page (TIMER and `scripts` injected first), lets it run (P when it starts paused)
    and waits out `warm_frames` frames; returns the frame count then (web_profile.py too)."""
    for source in (TIMER,) + tuple(scripts):
        page.call("Page.addScriptToEvaluateOnNewDocument", source=source)
    page.open(base + ("?" + query if query else ""))
    if page.status()["paused"]:
        page.key("p", "KeyP", 80)
    page.wait(lambda: not page.status()["paused"], "the simulation to run")
    start = page.evaluate(FRAME_COUNT)
    page.wait(lambda: page.evaluate(FRAME_COUNT) >= start + warm_frames, "warm-up frames")
    return page.evaluate(FRAME_COUNT)


def frame_ms(base, query, ratio):
    """The median and the 95th percentile of the frames' JavaScript (ms)."""
    page = browser_test.Page(1280, 720, ratio)
    try:
        count = FRAME_COUNT
        start = open_running(page, base, query, WARM_FRAMES)
        page.wait(lambda: page.evaluate(count) >= start + FRAMES, "the measured frames")
        times = page.evaluate(f"window.sandboxFrameMs.slice({start}, {start + FRAMES})")
        return statistics.median(times), percentile(times, 0.95)
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
    rounds, only = 3, None
    if "--rounds" in args:
        at = args.index("--rounds")
        rounds = int(args[at + 1])
        del args[at:at + 2]
    if "--only" in args:  # the cases whose names contain this (while working on one)
        at = args.index("--only")
        only = args[at + 1]
        del args[at:at + 2]
    if not args:
        print(__doc__)
        return 2
    cases = [c for c in CASES if only is None or only in c[0]]
    print("load average at the start: %.2f %.2f %.2f" % os.getloadavg(), flush=True)
    servers = {site: serve(site) for site in args}
    # Per site and case, one (median, 95th percentile) per round; the first frame: one figure.
    results = {site: {name: [] for name, _, _ in cases} for site in args}
    first = {site: [] for site in args}
    for r in range(rounds):
        for site in args:  # in turns, so that the load changes both alike
            base = servers[site][1]
            for name, query, ratio in cases:
                results[site][name].append(frame_ms(base, query, ratio))
            if only is None:
                first[site].append(first_frame_ms(base))
            print(f"round {r + 1}/{rounds}: {site}: " + ", ".join(
                f"{k} {v[-1][0]:.2f} / {v[-1][1]:.2f} ms" for k, v in results[site].items()) +
                (f", first frame {first[site][-1]:.0f} ms" if first[site] else ""), flush=True)
    print(f"\nmedians of {rounds} rounds of the JavaScript per frame (median / 95th percentile of "
          f"{FRAMES} frames), 1280x720, ratio 1 unless said; the first frame (warm) after:")
    for site in args:
        print(f"  {site}: " + ", ".join(
            f"{k} {statistics.median(m for m, _ in v):.2f} / "
            f"{statistics.median(p for _, p in v):.2f} ms" for k, v in results[site].items()) +
            (f", first frame {statistics.median(first[site]):.0f} ms" if first[site] else ""))
    print("load average at the end: %.2f %.2f %.2f" % os.getloadavg())
    before = results[args[0]]  # each later site's medians as a share of the first one's
    for site in args[1:]:
        after = results[site]
        print(f"  {site} / {args[0]} (medians): " + ", ".join(
            f"{k} {statistics.median(m for m, _ in after[k]) / statistics.median(m for m, _ in v):.2f}"
            for k, v in before.items()))
    for server, _ in servers.values():
        server.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
