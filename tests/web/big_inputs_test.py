#!/usr/bin/python3
"""The browser never hangs silently (issue 41): input past its limits is refused with a message
on the page, long work shows progress and keeps the page answering keys. Driven like
browser_test.py (headless Chromium over the DevTools protocol, its Page); one check per run:

  big-files   a scene whose name is 20 MB, a scene of 200,000 blocks, a 20 MB trace of the
              student's engine, a scene with a 10 MB description, and the worst files the
              browser accepts (the densest scene and a trace as large as browser_limits.h lets
              them be), each given to the page's file picker: each either opens with its
              progress shown on the page (a trace: compared one run a frame, "Comparing NAME
              with the reference: run K of N..." shown for each), or is refused
              with a message on the page (the panel's error and the page's live region); no
              uncaught exception; while it opens, a key is sent every 0.2 s and the time the
              page takes to take it is measured (reported, not checked: no test reads a clock
              to pass or fail); after it, F1 still opens the help
  url-range   a URL value out of its range (?lesson=lecture3&step=1000, step=99999999) is refused
              with a message naming the parameter and the range, and the rest opens (the lesson
              at its first step)
  page-error  a JavaScript exception inside a frame (the page's own service that the app calls,
              made to throw once) is said in the panel's error, and the frames go on (C++'s
              catch does not catch it: uncaught, it ended the main loop, the page frozen)

Exit 0: passed; 1: failed; 77: skipped (as browser_test.py).

usage: big_inputs_test.py SITE_DIR CHECK
"""
import json
import os
import re
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser_test as bt  # noqa: E402 (its Page, its server, its skip rules)
import websocket  # noqa: E402 (python3-websocket: browser_test.py skipped without it)

check = bt.check


def browser_limit(name):
    """A limit of browser_limits.h in bytes (`inline constexpr ... kName = 128u << 10;`), so the
    inputs at the limit follow it."""
    header = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "app", "gui",
                          "browser", "browser_limits.h")
    with open(header) as f:
        m = re.search(name + r" = (\d+)u << (\d+);", f.read())
    return int(m.group(1)) << int(m.group(2))


SCENE_LIMIT = browser_limit("kMaxBrowserSceneBytes")
TRACE_LIMIT = browser_limit("kMaxBrowserTraceBytes")


def dense_scene_js(limit):
    """The densest scene (the most blocks a byte: about 32 bytes each, at integer positions)
    with as many blocks as `limit` bytes hold."""
    return ("(() => { const b = []; let n = 70; for (let i = 0; ; ++i) { "
            "const r = '{\"position\":[' + (i % 500) + ',' + Math.floor(i / 500) + "
            "'],\"size\":0.5}'; if (n + r.length + 1 > " + str(limit) + ") break; b.push(r); "
            "n += r.length + 1; } return '{\"name\":\"dense\",\"world\":{\"bounds\":"
            "[-1,-1,500,1000]},\"blocks\":[' + b.join(',') + ']}'; })()")


def trace_js(limit):
    """lecture_example_1's blocks (m1 at 6 m/s, m2 at rest) frame by frame, up to `limit` bytes."""
    return (f"(() => {{ const rows = ['t,m1_x,m1_y,m1_vx,m1_vy,m2_x,m2_y,m2_vx,m2_vy']; "
            f"let n = rows[0].length + 1; for (let k = 1; ; ++k) {{ const t = k / 60; "
            "const r = t.toFixed(6) + ',' + (4 + 6 * t).toFixed(9) + ',6,6,0,8.75,6,0,0'; "
            f"if (n + r.length + 1 > {limit}) break; rows.push(r); n += r.length + 1; }} "
            "return rows.join('\\n') + '\\n'; })()")


# Each input as the page makes it (JavaScript that returns the file's text), its file name, and
# the shipped scene the page shows first (a trace is opened on the scene it traces).
TWENTY_MB = 20 << 20
INPUTS = [
    ("a 20 MB name", "name_20mb.json", "",
     f"'{{\"name\": \"' + 'A'.repeat({TWENTY_MB}) + "
     "'\", \"blocks\": [{\"position\": [5, 5], \"size\": 1}]}'"),
    ("200,000 blocks", "blocks_200000.json", "",
     "(() => { const b = []; for (let i = 0; i < 200000; ++i) b.push('{\"position\": [' + "
     "(i % 500 + 0.5) + ', ' + (Math.floor(i / 500) + 0.5) + '], \"size\": 0.5, \"velocity\": [' "
     "+ (i % 7 - 3) + ', ' + (i % 5 - 2) + ']}'); return '{\"name\": \"200000 blocks\", "
     "\"world\": {\"bounds\": [0, 0, 500, 400], \"gravity\": [0, 0]}, \"blocks\": [' + b.join(',\\n') "
     "+ ']}'; })()"),
    ("a 20 MB trace", "trace_20mb.csv", "?scene=lecture_example_1", trace_js(TWENTY_MB)),
    ("a 10 MB description", "description_10mb.json", "",
     f"'{{\"name\": \"long\", \"description\": \"' + 'word '.repeat({10 << 20} / 5) + "
     "'\", \"blocks\": [{\"position\": [5, 5], \"size\": 1}]}'"),
    # The worst the browser accepts (the files as large as its limits let them be): each opens.
    ("the densest scene at the limit", "dense_at_limit.json", "", dense_scene_js(SCENE_LIMIT)),
    ("a trace at the limit", "trace_at_limit.csv", "?scene=lecture_example_1",
     trace_js(TRACE_LIMIT)),
]


def make_file(page, name, make_js):
    """The file made in the page (window.bigFile), before anything is measured."""
    page.evaluate(f"window.bigFile = new File([{make_js}], '{name}'); 0")


def pick_file(page):
    """window.bigFile handed to the page's file picker, as a user's pick would be."""
    page.evaluate("""(() => {
        const list = new DataTransfer();
        list.items.add(window.bigFile);
        const input = document.getElementById('file');
        input.files = list.files;
        input.dispatchEvent(new Event('change'));
    })()""")


def key_latency(page):
    """Seconds the page takes to take one key (Shift, which does nothing): Chromium answers
    Input.dispatchKeyEvent once the page's main thread has handled the event."""
    start = time.monotonic()
    for kind in ("rawKeyDown", "keyUp"):
        page.call("Input.dispatchKeyEvent", type=kind, key="Shift", code="ShiftLeft",
                  windowsVirtualKeyCode=16, nativeVirtualKeyCode=16)
    return (time.monotonic() - start) / 2


def wait_for(condition, seconds=30):
    """True once `condition()` holds, False after `seconds` (a page that no longer answers)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.1)
    return False


def settled(page, name):
    """The open's outcome once it is over: ("opened", status) or ("refused", status); None while
    it goes on."""
    s = page.status()
    if s is None or s.get("loading"):
        return None
    if s["scene"].endswith("/" + name) or (name.endswith(".csv") and
                                          s["traceFirstDifference"] is not None):
        return "opened", s
    if name in s["error"] or "20 MB" in s["error"] or "MB" in s["error"]:
        return "refused", s
    return None


def leave(page, base):
    """The page left for about:blank, and gone (its memory with it: no back-forward cache); what
    it kept in the browser (settings, the service worker and its files) forgotten, as in a new
    Chromium."""
    page.call("Page.navigate", url="about:blank")

    def gone():
        try:
            return page.evaluate("location.href") == "about:blank"
        except AssertionError as e:  # asked while the old page went
            if any(w in str(e) for w in ("navigated or closed", "Execution context was destroyed",
                                         "Cannot find context")):
                return False
            raise

    page.wait(gone, "the last input's page to go")
    origin = re.match(r"https?://[^/]+", base).group(0)
    page.call("Storage.clearDataForOrigin", origin=origin, storageTypes="all")


def big_files(base):
    """Each input in a new page of one Chromium (a Chromium each cost a start and a stop: CI
    time): the last input's page is left first, and its errors forgotten; a new Chromium after
    an input that failed or hung (its page may still be busy). Whatever happens, no Chromium is
    left running."""
    failures = []
    page = None
    for what, name, query, make_js in INPUTS:
        page = one_input(page, base, what, name, query, make_js, failures)
    if page:
        page.close()
    check(not failures, f"{len(failures)} of {len(INPUTS)} inputs failed")


def one_input(page, base, what, name, query, make_js, failures):
    """One input opened in `page` (None: a new Chromium); returns the page for the next input,
    None when this one failed (the next starts a new Chromium)."""
    fresh = page is None
    if fresh:
        page = bt.Page(1280, 720, flags=("--disable-features=BackForwardCache",))
    started = time.monotonic()
    try:
        if not fresh:
            leave(page, base)
        page.errors.clear()  # this input's page's errors only
        page.open(base + query)
        page.evaluate("window.sandboxProgressLog = []")
        make_file(page, name, make_js)
        # The page's tasks over 50 ms (Chromium's long tasks) from the pick on: the longest
        # is how long the open held the page's one thread, keys waiting meanwhile.
        page.evaluate("window.longestTask = 0; new PerformanceObserver(list => { "
                      "for (const e of list.getEntries()) window.longestTask = "
                      "Math.max(window.longestTask, e.duration); })"
                      ".observe({entryTypes: ['longtask']}); 0")
        started = time.monotonic()
        pick_file(page)
        latencies, outcome = [], None
        deadline = started + bt.HANG_GUARD_S * 3
        while outcome is None:
            check(time.monotonic() < deadline, f"{what}: neither opened nor refused")
            latencies.append(key_latency(page))
            outcome = settled(page, name)
            time.sleep(0.2)
        took = time.monotonic() - started
        how, s = outcome
        progress = page.evaluate("window.sandboxProgressLog")
        longest = page.evaluate("window.longestTask")
        # The live region says a refusal on the next frames (the app's message, when it
        # changes, is announced as the page's state is sent).
        def live_text():
            return page.evaluate("document.getElementById('reader-live').textContent")
        if how == "refused":
            wait_for(lambda: s["error"][:60] in live_text(), 10)
        live = live_text()
        # The page still answers: F1 opens the help.
        page.key("F1", "F1", 112)
        answered = wait_for(lambda: page.status()["helpOpen"])
        page.wait_frames(2)
        said = f"progress shown {len(progress)} times" if how == "opened" else repr(s["error"][:160])
        print(f"{what}: {how} after {took:.1f} s ({said}); the page took a key in "
              f"{statistics.median(latencies) * 1000:.0f} ms median, "
              f"{max(latencies) * 1000:.0f} ms at most ({len(latencies)} keys), its longest "
              f"task {longest:.0f} ms (reported, not checked); F1 "
              f"{'opened' if answered else 'did not open'} the help after",
              flush=True)
        if name.endswith("_at_limit" + os.path.splitext(name)[1]):
            check(how == "opened", f"{what}: refused, though within the browser's limit")
        if how == "opened":
            check(progress, f"{what}: opened with no progress shown on the page")
            if name.endswith(".csv"):
                # Compared one run a frame, each said on the page (browser/trace_opening.h).
                runs = [p for p in progress if p.startswith("Comparing " + name)]
                check(len(runs) >= 3 and re.search(r": run (\d+) of \1\.\.\.$", runs[-1]),
                      f"{what}: not compared run by run with its progress shown: {progress}")
        else:
            check(s["error"] and s["error"][:60] in live,
                  f"{what}: refused, but the page's live region does not say it: {live!r}")
        check(answered, f"{what}: F1 did not open the help after it")
        check(not page.errors, f"{what}: the console has errors:\n" + "\n".join(page.errors))
    except AssertionError as e:  # every input is tried and reported
        print(f"FAILED: {e}", flush=True)
        failures.append(str(e))
        page.close()
        return None
    except websocket.WebSocketTimeoutException:
        took = time.monotonic() - started
        print(f"FAILED: {what}: the page answered nothing for {bt.HANG_GUARD_S} s "
              f"({took:.0f} s after the file was given)", flush=True)
        failures.append(f"{what}: hung")
        page.close()
        return None
    except BaseException:  # anything else ends the check: its Chromium with it
        page.close()
        raise
    return page


def url_range(base):
    page = bt.Page(1280, 720)
    try:
        for step in ("1000", "99999999"):
            page.open(base + f"?lesson=lecture3&step={step}")
            s = page.status()
            check(s["lessonStep"] == 1, f"step={step}: the lesson is not open at its first step: {s}")
            check(re.search(r"URL parameter step: '\d+' is not a step of 'lecture3' \(1 to \d+\)",
                            s["error"]),
                  f"step={step}: the message does not name the parameter and its range: {s['error']!r}")
            print(f"?lesson=lecture3&step={step}: the lesson at step 1, and {s['error']!r}")
        check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
    finally:
        page.close()


def page_error(base):
    page = bt.Page(1280, 720)
    try:
        page.open(base)
        page.key("p", "KeyP", 80)  # running: the page's text changes, showState is called
        page.evaluate("""(() => {
          const showState = window.sandboxPage.showState;
          window.sandboxPage.showState = function () {
            if (!window.sandboxThrown) {
              window.sandboxThrown = true;
              throw new Error('showState failed on purpose');
            }
            return showState.apply(this, arguments);
          };
        })()""")
        check(wait_for(lambda: page.evaluate("window.sandboxThrown === true")),
              "the page's showState was never called")
        frames = page.status()["frames"]
        check(wait_for(lambda: page.status()["frames"] >= frames + 10),
              "the frames stopped after a JavaScript exception in a frame")
        s = page.status()
        check("JavaScript: showState failed on purpose" in s["error"],
              f"the panel does not say the JavaScript exception: {s['error']!r}")
        page.key("p", "KeyP", 80)  # the keys still work
        check(wait_for(lambda: page.status()["paused"]), "P does not pause after the exception")
        print(f"after the exception: {s['error']!r}; frames go on, P pauses")
    finally:
        page.close()


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    site, what = sys.argv[1], sys.argv[2]
    return bt.run_site(site, {"big-files": big_files, "url-range": url_range,
                                 "page-error": page_error}[what])


if __name__ == "__main__":
    sys.exit(main())
