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


def grid(columns, rows, size, speed=3.0, extra_world=None):
    """A gas of columns x rows blocks in [0, 20] x [0, 12], C = 1, no gravity."""
    pitch_x, pitch_y = 20.0 / columns, 12.0 / rows
    blocks = []
    for i in range(columns * rows):
        c, r = i % columns, i // columns
        angle = 2.399963 * i
        blocks.append({"position": [(c + 0.5) * pitch_x, (r + 0.5) * pitch_y], "size": size,
                       "velocity": [round(speed * (0.3 + (i % 7) / 10) * (-1) ** i, 3),
                                    round(speed * ((i * 0.618) % 1 - 0.5), 3)],
                       "color": "#40a050" if angle > 0 else "#d04040"})
    world = {"bounds": [0, 0, 20, 12], "gravity": [0, 0], "bounciness": 1}
    world.update(extra_world or {})
    return {"name": "gas %d" % (columns * rows), "world": world, "blocks": blocks}


def memory_line(text_json):
    """The timeline's memory line: (timeline MB, its cap, trails MB, their cap) or None."""
    texts = json.loads(read(text_json))["texts"]
    for t in texts:
        m = re.search(r"([\d.]+) MB of (\d+); trails ([\d.]+) MB of (\d+)", t["text"])
        if m:
            return tuple(float(v) for v in m.groups())
    return None


def run_cases(suite):
    folder = suite.folder("memory")
    big = os.path.join(folder, "gas20000.json")
    with open(big, "w") as f:
        json.dump(grid(200, 100, 0.04), f)
    # Past both caps: 20,000 blocks fill 32 MB of trails in about 50 frames and 128 MB of
    # keyframes in well under 2,000 (a keyframe of 20,000 blocks is about 1.7 MB).
    peaks = {}
    for frames in (1500, 3000):
        shot = os.path.join(folder, "gas_%d.png" % frames)
        text = os.path.join(folder, "gas_%d.json" % frames)
        result = run([suite.offscreen, big, "--frames", frames, "--show", ALL_OVERLAYS,
                      "--screenshot", shot, "--text-json", text], folder, timeout=900,
                     mem_mb=3072)
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
            if frames == 3000 and timeline < cap - 4:
                problems.append("the timeline did not reach its cap (%g MB)" % timeline)
        peaks[frames] = result.maxrss_kb
        print("     %d frames of 20,000 blocks, every overlay: peak RSS %d kB, memory line %s" %
              (frames, result.maxrss_kb, line))
        suite.check("20,000-block gas, every overlay, %d frames" % frames, problems, result)
    if len(peaks) == 2:
        growth = peaks[3000] - peaks[1500]
        # Flat past the caps: twice the frames may add what the caps still allowed at 1,500
        # frames (the timeline had not yet filled its 128 MB there), never more than that.
        suite.check("twice as long past the caps stays within the caps (+%d kB)" % growth,
                    [] if growth < 128 * MB else ["peak RSS grew by %d kB" % growth])

    # Held keys: a keyframe every frame while input is held (README): 600 s at 1,000 frames
    # a second, one player block, its right key held all along.
    player = {"name": "runner", "world": {"bounds": [-1e6, 0, 1e6, 12], "drag": 1},
              "blocks": [{"name": "p", "position": [0, 1], "size": 1}],
              "player": {"block": "p", "force": 20, "jump": 5}}
    lesson = os.path.join(folder, "held.json")
    with open(lesson, "w") as f:
        json.dump({"name": "held", "steps": [{
            "title": "held", "caption": "the right key held for ten minutes", "scene": player,
            "overrides": {"frame_rate": 1000}, "overlays": ALL_OVERLAYS.split(","),
            "select": "p", "input": [{"at": 0, "hold": ["right"], "for": 600}],
            "pause_at": {"time": 600}}]}, f)
    for program, args in [
            ("sandbox-cli lesson", [suite.cli, "lesson", lesson]),
            ("offscreen --lesson", [suite.offscreen, "--lesson", lesson, "--screenshot",
                                    os.path.join(folder, "held.png")])]:
        result = run(args, folder, timeout=900, mem_mb=1536)
        problems = suite.accepted(result)
        if result.maxrss_kb > 512 * MB:
            problems.append("peak RSS %d kB for one block" % result.maxrss_kb)
        print("     held key 600 s at 1 kHz [%s]: peak RSS %d kB" % (program, result.maxrss_kb))
        suite.check("held key for 600 s [%s]" % program, problems, result)

    # A lesson of 1,000 steps naming one 20,000-block scene file: read once, held once.
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
        json.dump(grid(2, 1, 1), f)
    result = run([suite.offscreen, small, "--frames", "10000000", "--audio-wav",
                  os.path.join(folder, "a.wav")],
                 folder, timeout=60, mem_mb=1536)
    problems = suite.refused(result, ["--audio-wav"], code=1)
    if os.path.exists(os.path.join(folder, "a.wav")):
        problems.append("a.wav written")
    suite.check("a recording's sound beyond 64 MB", problems, result)

    # A long headless run keeps nothing per frame.
    result = run([suite.cli, "run", small, "--steps", "3000000", "--json"], folder, timeout=300,
                 mem_mb=512)
    problems = suite.accepted(result)
    if result.maxrss_kb > 64 * MB:
        problems.append("peak RSS %d kB for two blocks" % result.maxrss_kb)
    suite.check("3,000,000 frames headless", problems, result)
