#!/usr/bin/python3
"""The class poll in the window (issue 40), offscreen at 1920x1080, UI scale 1.5, as a projector
shows it. The poll is served on 127.0.0.1 only; the votes are fed by --poll-votes (as phones
would send them, without a network).

  setup    at the step's setup with 24 votes cast: the QR code decodes (zbarimg, Debian's
           zbar-tools) to the URL the window prints; it shows "24 joined · 24 voted" and no count
           of any choice (the histogram stays hidden while the vote is open)
  moment   at the moment after two rounds (3,17,4 then 1,22,1): every choice's letter, count and
           percentage of both rounds in the classroom's text size (as large as the lesson
           caption's text), "proved by the run" on the proved choice's row only

usage: poll_window_test.py SANDBOX_OFFSCREEN LESSON STEP PROVED CHECK OUT_DIR
Exit 0 passed, 1 failed, 77 skipped (no zbarimg). Timeouts only guard against a hang.
"""
import json
import os
import shutil
import subprocess
import sys

from poll_client import run_test

SKIP = 77


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def render(offscreen, lesson, step, out, name, *extra):
    png = os.path.join(out, name + ".png")
    texts = os.path.join(out, name + ".text.json")
    run = subprocess.run([offscreen, "--lesson", lesson, "--step", step, "--poll", "127.0.0.1",
                          "--size", "1920x1080", "--ui-scale", "1.5", "--screenshot", png,
                          "--text-json", texts, *extra],
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, "sandbox-offscreen failed: %s" % run.stderr)
    with open(texts) as f:
        return png, json.load(f)["texts"]


def poll_texts(texts):
    return [t for t in texts if t["window"] == "Class poll"]


def caption_px(texts):
    sizes = [t["px"] for t in texts if t["window"] in ("Lesson caption", "caption")]
    check(sizes, "no lesson caption text")
    return min(sizes)


def setup_check(offscreen, lesson, step, proved, out):
    png, texts = render(offscreen, lesson, step, out, "poll_setup", "--at", "setup",
                        "--poll-votes", "3,17,4")
    mine = poll_texts(texts)
    urls = [t["text"] for t in mine if t["text"].startswith("http://127.0.0.1:")]
    check(len(urls) == 1, "the URL once in the poll window: %s" % [t["text"] for t in mine])
    decoded = subprocess.run(["zbarimg", "--quiet", "--raw", png], capture_output=True,
                             text=True, timeout=120)
    check(decoded.returncode == 0, "zbarimg found no QR code in %s" % png)
    check(decoded.stdout.strip() == urls[0],
          "the QR code says %r, the window %r" % (decoded.stdout.strip(), urls[0]))
    joined = " ".join(t["text"] for t in mine)
    check("24 joined \u00b7 24 voted" in joined, "counts line: %s" % joined)
    check(not any("(" in t["text"] and "%" in t["text"] for t in mine),
          "a count shows while the vote is open: %s" % joined)
    px = caption_px(texts)
    for t in mine:
        if t["text"] == urls[0]:
            check(t["px"] >= px - 0.5, "the URL at %s px, the caption's %s" % (t["px"], px))
    print("QR decoded:", urls[0])


def moment_check(offscreen, lesson, step, proved, out):
    png, texts = render(offscreen, lesson, step, out, "poll_moment",
                        "--poll-votes", "3,17,4/1,22,1")
    mine = poll_texts(texts)
    words = [t["text"] for t in mine]
    px = caption_px(texts)
    expected = ["3 (13%)", "17 (71%)", "4 (17%)", "1 (4%)", "22 (92%)"]
    for label in expected:
        found = [t for t in mine if t["text"] == label]
        check(found, "%r not in the poll window: %s" % (label, words))
        check(all(t["px"] >= px - 0.5 for t in found),
              "%r at %s px, smaller than the caption's %s" % (label, found[0]["px"], px))
        check(not any(t["clipped"] for t in found), "%r is clipped" % label)
    letters = [t for t in mine if t["text"] in ("A", "B", "C")]
    check(sorted(t["text"] for t in letters) == ["A", "B", "C"], "letters: %s" % words)
    rows = sorted(letters, key=lambda t: t["rect"][1])
    marks = [t for t in mine if "proved by the run" in t["text"]]
    check(len(marks) == 1, "one proved mark: %s" % words)
    mark_y = marks[0]["rect"][1]
    proved_row = rows[proved]["rect"][1]
    next_row = rows[proved + 1]["rect"][1] if proved + 1 < len(rows) else 1e9
    check(proved_row < mark_y < next_row,
          "the proved mark at y %s, not under %s's row" % (mark_y, "ABC"[proved]))
    print("histogram:", [w for w in words if "(" in w], "marked", "ABC"[proved])


def main():
    offscreen, lesson, step, proved, name, out = sys.argv[1:7]
    if not shutil.which("zbarimg"):
        print("zbarimg (zbar-tools) is missing: skipped")
        return SKIP
    os.makedirs(out, exist_ok=True)
    {"setup": setup_check, "moment": moment_check}[name](offscreen, lesson, step, int(proved),
                                                         out)
    print("passed")
    return 0


if __name__ == "__main__":
    run_test(main)
