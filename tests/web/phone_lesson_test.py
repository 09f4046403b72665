#!/usr/bin/python3
"""The lesson on a touch screen (issue 39's phone rules), in headless Chromium as browser_test.py
drives it: a phone held upright (390x844 CSS px at ratio 3) and a tablet (1024x768 at ratio 2),
both touch screens. For lecture3's steps 3, 10 and 13, at the setup and at the moment (reached by
tapping the bar's Play, which in a lesson plays to the moment and stops there):

  - the caption takes at most a third of the screen's height (the rest folds behind "(more)")
  - the bar (Play) is on the screen, not under the caption, with the sheet closed and open
  - the scene has at least 40% of the screen at the moment
  - every control drawn is at least 44 CSS px on its short side, scrollbars too
  - no text names a key (PageDown, F1, ...): a touch screen has none to press
  - a tap on the caption's "(more)" shows the whole caption, within a third of the height or
    scrolling there, and a second tap folds it

It prints the figures measured, per size and step. Controls come from the page's
sandbox_web_controls (ImGui's item hooks), texts from sandbox_web_texts (screen_text.h).
Nothing is timed: each wait is for a condition, guarded only against a hang.

usage: phone_lesson_test.py SITE_DIR [CHECK] [SHOTS_DIR]   (CHECK: phone-lesson, the default)
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser_test as bt  # noqa: E402 (its Page, its server, its skip rules)
from browser_test import Page  # noqa: E402

SIZES = ((390, 844, 3), (1024, 768, 2))
STEPS = (3, 10, 13)
LEAST_CONTROL_PX = 44.0
# A key's name as a hint says it ("PageDown", "press P", "F1"): none on a touch screen.
KEY_WORDS = re.compile(r"\b(PageDown|PageUp|PgDn|PgUp|F1|F5|F6|Esc|Enter|Shift|Ctrl|Space|"
                       r"press [A-Z]\b|\([A-Z]\))")


FAILURES = []


def failed(message):
    """A rule broken: said at once, and the check fails at its end (every figure measured)."""
    print("  FAIL:", message)
    FAILURES.append(message)


def css(rect, ratio):
    return [v / ratio for v in rect]


def controls(page):
    """The last frame's controls drawn on the screen (CSS px) and the narrowest scrollbar."""
    doc = json.loads(page.evaluate("Module.ccall('sandbox_web_controls', 'string', [], [])"))
    ratio = page.evaluate("devicePixelRatio")
    shown = [dict(c, rect=css(c["rect"], ratio)) for c in doc["controls"] if c["visible"]]
    return shown, doc["scrollbar"] / ratio


def page_controls(page):
    """The page's own controls shown over the canvas (buttons, fields, links), CSS px; those
    kept for screen readers and the keyboard only (1 px, clipped away) are not touch targets."""
    return page.evaluate("""[...document.querySelectorAll('button, input, select, a, [role=button]')]
        .filter(e => { const r = e.getBoundingClientRect(), s = getComputedStyle(e);
            return r.width > 1 && r.height > 1 && s.visibility !== 'hidden' && s.display !== 'none'
                && e.offsetParent !== null && r.bottom > 0 && r.top < innerHeight; })
        .map(e => { const r = e.getBoundingClientRect();
            return {label: (e.innerText || e.value || e.id || '').trim(), window: 'page',
                    rect: [r.left, r.top, r.width, r.height]}; })""")


def texts(page):
    ratio = page.evaluate("devicePixelRatio")
    doc = json.loads(page.evaluate("Module.ccall('sandbox_web_texts', 'string', [], [])"))
    return [dict(t, rect=css(t["rect"], ratio)) for t in doc["texts"]]


def fresh_controls(page):
    """Controls of a frame drawn after this call (the hooks are on from the first call)."""
    controls(page)
    page.wait_frames(2)
    return controls(page)


def find(items, label, window=None):
    for c in items:
        if c["label"] == label and (window is None or c["window"] == window):
            return c
    return None


def overlaps(a, b):
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


def centre(rect):
    return rect[0] + rect[2] / 2, rect[1] + rect[3] / 2


def measure(page, w, h, what):
    """The figures of the frame shown, checked against the rules; returns them."""
    s = page.status()
    items, scrollbar = fresh_controls(page)
    items += page_controls(page)
    caption = s["captionHeight"]
    if caption > h / 3 + 0.5:
        failed(f"{what}: the caption is {caption:.0f} of {h} px (more than a third)")
    scene = s["sceneOnScreen"]
    share = scene[2] * scene[3] / (w * h)
    play = find(items, "Play") or find(items, "Pause") or find(items, "Next") or \
        find(items, "Play >") or find(items, "Next >")
    if play is None:
        raise AssertionError(f"{what}: no Play, Pause or Next on the screen: {[c['label'] for c in items]}")
    r = play["rect"]
    if not (r[0] >= 0 and r[1] >= caption - 0.5 and r[0] + r[2] <= w + 0.5 and r[1] + r[3] <= h + 0.5):
        failed(f"{what}: the bar's {play['label']} at {r} is off the screen or under the caption "
               f"({caption:.0f} px)")
    small = [c for c in items if min(c["rect"][2], c["rect"][3]) < LEAST_CONTROL_PX - 0.01]
    if small:
        listed = ", ".join(f"{c['label'] or '(unnamed)'} in {c['window']} "
                           f"{c['rect'][2]:.1f}x{c['rect'][3]:.1f}" for c in small[:12])
        failed(f"{what}: {len(small)} controls under {LEAST_CONTROL_PX:.0f} CSS px: {listed}")
    if 0 < scrollbar < LEAST_CONTROL_PX - 0.01:
        failed(f"{what}: a scrollbar {scrollbar:.1f} CSS px wide")
    keyed = [t["text"] for t in texts(page) if KEY_WORDS.search(t["text"])]
    if keyed:
        failed(f"{what}: texts name keys on a touch screen: {keyed[:5]}")
    smallest = min(min(c["rect"][2], c["rect"][3]) for c in items)
    return {"caption": caption, "scene": share, "smallest": smallest, "controls": len(items),
            "play": play}


def play_to_moment(page, what, play):
    page.tap(*centre(play["rect"]))
    page.wait(lambda: page.status()["lessonPhase"] == 2 and page.status()["paused"],
              f"{what}: the step to stop at its moment after Play")
    page.wait_frames(3)
    s = page.status()
    if not s["revealed"]:
        failed(f"{what}: stopped, but the answer is not shown")


def sheet_open_keeps_bar(page, w, h, what):
    """Controls opened on a phone: the bar stays below the caption; closed again."""
    s = page.status()
    if not s["sheet"]:
        return None
    items, _ = fresh_controls(page)
    opener = find(items, "Controls")
    if not opener:
        raise AssertionError(f"{what}: no Controls button in the sheet's bar")
    page.tap(*centre(opener["rect"]))
    page.wait(lambda: page.status()["sheetOpen"], f"{what}: the sheet to open")
    s = page.status()
    items, _ = fresh_controls(page)
    close = find(items, "Close")
    if not close or close["rect"][1] < s["captionHeight"] - 0.5:
        failed(f"{what}: with Controls open the bar is under the caption: {close} "
               f"(caption {s['captionHeight']:.0f} px)")
    small = [c for c in items if min(c["rect"][2], c["rect"][3]) < LEAST_CONTROL_PX - 0.01]
    if small:
        failed(f"{what}, Controls open: controls under 44 CSS px: "
               + ", ".join(f"{c['label']} {c['rect'][2]:.1f}x{c['rect'][3]:.1f}" for c in small[:12]))
    page.tap(*centre(close["rect"]))
    page.wait(lambda: not page.status()["sheetOpen"], f"{what}: the sheet to close")
    return min(min(c["rect"][2], c["rect"][3]) for c in items)


def more_opens_and_folds(page, w, h, what):
    """A cut caption's "(more)": tapped, the whole caption within a third of the height (or
    scrolling there); tapped again, folded."""
    cut = [t for t in texts(page) if t["window"] == "caption" and "(more)" in t["text"]]
    if not cut:
        return False
    page.tap(*centre(cut[0]["rect"]))
    page.wait_frames(3)
    opened = [t for t in texts(page) if t["window"] == "caption"]
    if any("(more)" in t["text"] for t in opened):
        failed(f"{what}: a tap on (more) did not open the caption")
    bottom = max(t["rect"][1] + t["rect"][3] for t in opened)
    items, _ = fresh_controls(page)
    if bottom > h / 3 + 0.5 and page.status()["captionHeight"] > h / 3 + 0.5:
        failed(f"{what}: the opened caption reaches {bottom:.0f} px of {h}")
    page.tap(w / 2, 10)
    page.wait_frames(3)
    if not any("(more)" in t["text"] for t in texts(page) if t["window"] == "caption"):
        failed(f"{what}: a second tap did not fold the caption")
    return True


def shot(page, shots_dir, name):
    if shots_dir:
        path = os.path.join(shots_dir, name + ".png")
        open(path, "wb").write(page.screenshot())
        print("  screenshot", path)


def phone_lesson(base, sizes, shots_dir=None):
    for w, h, ratio in sizes:
        page = Page(w, h, ratio, touch=True)
        try:
            for step in STEPS:
                page.open(base + f"?lesson=lecture3&step={step}")
                page.wait(lambda: page.status()["lessonStep"] == step, f"step {step}")
                controls(page)  # the hooks on
                page.wait_frames(3)
                what = f"{w}x{h} step {step} setup"
                setup = measure(page, w, h, what)
                shot(page, shots_dir, f"phone_lesson_{w}x{h}_step{step}_setup")
                opened = sheet_open_keeps_bar(page, w, h, what)
                folded = more_opens_and_folds(page, w, h, what)
                setup = measure(page, w, h, what)
                play_to_moment(page, what, setup["play"])
                what = f"{w}x{h} step {step} moment"
                moment = measure(page, w, h, what)
                shot(page, shots_dir, f"phone_lesson_{w}x{h}_step{step}_moment")
                if moment["scene"] < 0.4:
                    failed(f"{what}: the scene has {moment['scene']:.0%} of the screen")
                print(f"{w}x{h} step {step}: caption {setup['caption']:.0f} px at the setup, "
                      f"{moment['caption']:.0f} at the moment (at most {h / 3:.0f}); the scene "
                      f"{setup['scene']:.0%} / {moment['scene']:.0%}; smallest control "
                      f"{min(setup['smallest'], moment['smallest']):.1f} CSS px of "
                      f"{setup['controls']} / {moment['controls']}"
                      + (f", {opened:.1f} with Controls open" if opened else "")
                      + ("; (more) opens and folds" if folded else ""))
            if page.errors:
                failed("the console has errors:\n" + "\n".join(page.errors))
        finally:
            page.close()
    if FAILURES:
        raise AssertionError(f"{len(FAILURES)} rules broken (above)")


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    shots_dir = sys.argv[3] if len(sys.argv) > 3 else None
    if shots_dir:
        os.makedirs(shots_dir, exist_ok=True)
    # phone-lesson: the phone; tablet-lesson: the tablet (ctest runs each as its own test).
    sizes = [s for s in SIZES if (s[0] < 800) == (sys.argv[2:3] != ["tablet-lesson"])]
    return bt.run_site(sys.argv[1], lambda base: phone_lesson(base, sizes, shots_dir))


if __name__ == "__main__":
    sys.exit(main())
