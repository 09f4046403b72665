"""Memory in long runs (issue 28, "Memory stays bounded"), from the README's "Memory in long
runs": the timeline's keyframes 128 MB, the trails 32 MB, the plots' series under 2 MB, a
recording's sound 64 MB (refused before the run). A run past its caps stays flat: running twice
as long adds no more than a little to the peak resident set; every run also stays under an
address-space limit, so a leak fails the case instead of the machine. And a lesson that names
one big scene file from every step holds it once (docs/lesson-format.md, "Limits")."""
import json
import os
import re

from hostile_outside import read, run

ALL_OVERLAYS = "trails,vectors,plots,inspector,com,poi,timeline,velocityspace,sidebyside"
MB = 1024  # kB


def resting_gas(columns, rows, size):
    """columns x rows blocks in [0, 20] x [0, 12], drifting at a centimetre a second (they never
    meet in the frames run): the memory of a big world without the cost of its collisions."""
    pitch_x, pitch_y = 20.0 / columns, 12.0 / rows
    blocks = [{"position": [(i % columns + 0.5) * pitch_x, (i // columns + 0.5) * pitch_y],
               "size": size, "velocity": [0.01 * (i % 7 - 3), 0.01 * (i % 5 - 2)]}
              for i in range(columns * rows)]
    return {"name": "gas %d" % (columns * rows), "world": {"gravity": [0, 0]}, "blocks": blocks}


def memory_line(text_json):
    """The timeline's memory line (its words may be drawn as several texts): (timeline MB, its
    cap, trails MB, their cap), or None."""
    words = " ".join(t["text"] for t in json.loads(read(text_json))["texts"])
    m = re.search(r"([\d.]+) MB of (\d+); trails ([\d.]+) MB of (\d+)", " ".join(words.split()))
    return tuple(float(v) for v in m.groups()) if m else None


def run_cases(suite):
    folder = suite.folder("memory")
    big = os.path.join(folder, "gas100000.json")
    with open(big, "w") as f:
        json.dump(resting_gas(400, 250, 0.02), f)
    # 100,000 blocks: a keyframe is about 9 MB, so the timeline's 128 MB are full after about
    # 14 keyframes (240 frames) and the trails' 32 MB after a few points a block. From there on
    # twice the frames may add only what the caps still allowed at 240 frames.
    # What is measured is what the program holds: glibc's mmap threshold is pinned at 1 MiB for
    # these runs, so a freed keyframe or world copy (9.6 MB) goes back to the system instead of
    # leaving a hole in the heap whose size depends on where the kernel placed the heap (a CI
    # run once measured +38 MB of such holes at 480 frames, where runs here measure +3 MB).
    pinned = dict(os.environ, GLIBC_TUNABLES="glibc.malloc.mmap_threshold=1048576")
    peaks = {}
    for frames in (240, 480):
        shot = os.path.join(folder, "gas_%d.png" % frames)
        text = os.path.join(folder, "gas_%d.json" % frames)
        result = run([suite.offscreen, big, "--frames", frames, "--show", ALL_OVERLAYS,
                      "--screenshot", shot, "--text-json", text], folder, timeout=1200,
                     mem_mb=3072, env=pinned)
        problems = suite.accepted(result)
        line = memory_line(text) if os.path.exists(text) else None
        if line is None:
            problems.append("no 'MB of 128; trails MB of 32' line in the text drawn")
        else:
            timeline, cap, trails, trails_cap = line
            if (cap, trails_cap) != (128, 32):
                problems.append("the caps shown are %g and %g MB, not 128 and 32" % (cap,
                                                                                     trails_cap))
            if timeline > cap or trails > trails_cap:
                problems.append("over a cap: %g of %g, trails %g of %g" % line)
            if timeline < cap - 16 or trails < trails_cap - 8:
                problems.append("a cap was not reached: %g of %g, trails %g of %g" % line)
            peaks[frames] = (result.maxrss_kb, timeline + trails)
        print("     %d frames of 100,000 blocks, every overlay: peak RSS %d kB, memory line %s" %
              (frames, result.maxrss_kb, line))
        suite.check("100,000 blocks, every overlay, %d frames" % frames, problems, result)
    if len(peaks) == 2:
        growth = peaks[480][0] - peaks[240][0]
        allowed = (128 + 32 - peaks[240][1]) * MB + 32 * MB  # what the caps left, and slack
        suite.check("twice as long past the caps stays flat (+%d kB)" % growth,
                    [] if growth < allowed else ["peak RSS grew by %d kB, more than %d kB" %
                                                 (growth, allowed)])

    # A lesson of 1,000 steps naming one 20,000-block scene file: read once, held once.
    with open(os.path.join(folder, "gas20000.json"), "w") as f:
        json.dump(resting_gas(200, 100, 0.04), f)
    steps = [{"title": "s%d" % i, "caption": "c", "scene": "gas20000.json",
              "pause_at": {"time": 0}} for i in range(1000)]
    many = os.path.join(folder, "many.json")
    with open(many, "w") as f:
        json.dump({"name": "many", "steps": steps}, f)
    result = run([suite.cli, "validate", many], folder, timeout=900, mem_mb=1536)
    problems = suite.accepted(result)
    if result.maxrss_kb > 512 * MB:
        problems.append("peak RSS %d kB: the scene is held more than once" % result.maxrss_kb)
    print("     1,000 steps of one 20,000-block scene: peak RSS %d kB" % result.maxrss_kb)
    suite.check("1,000 steps naming one 20,000-block scene [validate]", problems, result)

    # The recording's sound: refused before the run when longer than its cap.
    small = os.path.join(folder, "small.json")
    with open(small, "w") as f:
        json.dump(resting_gas(2, 1, 1), f)
    result = run([suite.offscreen, small, "--frames", "10000000", "--audio-wav",
                  os.path.join(folder, "a.wav")],
                 folder, timeout=60, mem_mb=1536)
    problems = suite.refused(result, ["--audio-wav"], code=1)
    if os.path.exists(os.path.join(folder, "a.wav")):
        problems.append("a.wav written")
    suite.check("a recording's sound beyond 64 MB", problems, result)

    # A long headless run keeps nothing per frame.
    result = run([suite.cli, "run", small, "--steps", "1000000", "--json"], folder, timeout=300,
                 mem_mb=512)
    problems = suite.accepted(result)
    if result.maxrss_kb > 64 * MB:
        problems.append("peak RSS %d kB for two blocks" % result.maxrss_kb)
    suite.check("1,000,000 frames headless", problems, result)
