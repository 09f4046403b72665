#!/usr/bin/python3
"""The class poll's phone page in a real browser (issue 40): headless Chromium as a phone
(390x844 CSS px at ratio 3, touch), driven over the DevTools protocol (tests/web's Page), on the
page sandbox-cli poll serves on 127.0.0.1.

The page shows step 2's question and its three lettered choices; axe-core (npm) finds no
violation; a tap on B votes (the button says "your vote", aria-pressed), and `close` counts it
exactly; a reload shows the same vote; after the close the page says the vote is closed and its
buttons are disabled; at 200% text nothing is wider than the screen and axe-core still finds no
violation; no console error on the way.

usage: phone_page_test.py SANDBOX_CLI LESSON
Exit 0 passed, 1 failed, 77 skipped (no chromium, python3-websocket or axe-core).
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "web"))
sys.path.insert(0, HERE)
import browser_test as web  # noqa: E402  (exits 77 without python3-websocket or python3-pil)
from poll_client import PollServer, run_test  # noqa: E402


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def tap(page, selector):
    """A finger's tap at the middle of the element (touch events, as a phone sends them)."""
    x, y = page.evaluate(
        "(() => { const r = document.querySelector(%s).getBoundingClientRect(); "
        "return [r.left + r.width / 2, r.top + r.height / 2]; })()" % json.dumps(selector))
    point = [{"x": x, "y": y}]
    page.call("Input.dispatchTouchEvent", type="touchStart", touchPoints=point)
    page.call("Input.dispatchTouchEvent", type="touchEnd", touchPoints=[])


def choices(page):
    return page.evaluate(
        "Array.from(document.querySelectorAll('.choice')).map(b => [b.textContent, "
        "b.getAttribute('aria-pressed'), b.disabled])") or []


def run(cli, lesson):
    server = PollServer(cli, lesson)
    page = web.Page(390, 844, pixel_ratio=3, touch=True)
    try:
        page.call("Page.setBypassCSP", enabled=True)  # axe-core is injected as a script
        check(server.command("open 2")["open"], "open 2")
        page.call("Page.navigate", url=server.url)
        page.wait(lambda: len(choices(page)) == 3, "the three choices")
        shown = choices(page)
        check([c[0][0] for c in shown] == ["A", "B", "C"], "letters: %s" % shown)
        check("Moves back" in shown[1][0], "choice B: %s" % shown)
        check(page.evaluate("document.getElementById('question').textContent").startswith(
            "m1 = 1 kg at 6 m/s"), "the question")
        found = web.axe_violations(page)
        check(not found, "axe-core on the phone page:\n" + "\n".join(found))
        heights = page.evaluate("Array.from(document.querySelectorAll('.choice'))"
                                ".map(b => b.getBoundingClientRect().height)")
        check(min(heights) >= 44, "buttons under 44 CSS px high: %s" % heights)
        tap(page, ".choice:nth-child(2)")
        page.wait(lambda: choices(page)[1][1] == "true", "B pressed")
        check("your vote" in choices(page)[1][0], "B says it is the vote: %s" % choices(page))
        check(server.command("status")["voted"] == 1, "one vote counted")
        # A reload (or a phone waking up) shows the same vote.
        page.call("Page.reload")
        page.wait(lambda: len(choices(page)) == 3 and choices(page)[1][1] == "true",
                  "the vote after a reload")
        # 200% text: it reflows, nothing wider than the screen, still accessible.
        page.evaluate("document.documentElement.style.fontSize = '200%'")
        wide = page.evaluate("document.documentElement.scrollWidth")
        check(wide <= 390, "at 200%% text the page is %s px wide" % wide)
        found = web.axe_violations(page)
        check(not found, "axe-core at 200% text:\n" + "\n".join(found))
        closed = server.command("close")
        check(closed["counts"] == [0, 1, 0] and closed["voters"] == 1, "close: %s" % closed)
        page.wait(lambda: "closed" in page.evaluate(
            "document.getElementById('status').textContent"), "the page saying closed")
        check(all(c[2] for c in choices(page)), "buttons still enabled after the close")
        page.evaluate("new Promise(r => setTimeout(r, 300))")
        check(not page.errors, "the console has errors:\n" + "\n".join(page.errors))
        print("axe-core: no violation; a tap on B counted:", closed)
    finally:
        page.close()
        server.kill()


def main():
    cli, lesson = sys.argv[1:3]
    if not os.path.exists(web.CHROMIUM):
        web.skip("chromium is not installed (scripts/web.sh deps installs it)")
    if not os.path.exists(web.AXE_JS):
        web.skip(f"{web.AXE_JS} is missing (scripts/web.sh deps installs axe-core)")
    run(cli, lesson)
    print("passed")
    return 0


if __name__ == "__main__":
    run_test(main)
