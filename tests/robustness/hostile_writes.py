"""Failed writes (issue 28, "Nothing written loses data"), from docs/cli.md, "Files written lose
nothing": a write that cannot be done exits non-zero naming the file, the file that was there is
intact byte for byte, and no temporary file is left beside it; an output may not be an input of
the same run by any spelling or link.

A full disk is /dev/full, and for a regular file that exists a file-size limit (ulimit -f, with
SIGXFSZ ignored so a write fails with EFBIG as on a full disk). A read-only folder needs a user
whom permissions bind: as root, those cases run as nobody."""
import json
import os

from hostile_outside import changed, read, run, snapshot, write

SCENE = {"name": "two", "world": {"gravity": [0, 0]},
         "blocks": [{"name": "m1", "position": [4, 6], "size": 1, "velocity": [6, 0]},
                    {"name": "m2", "position": [10, 6], "size": 1.5, "mass": 2}]}
OLD = b"the old file, which must survive\n"
FULL_DISK_BYTES = 256  # the file-size limit that stands for a full disk: more than OLD


def leftovers(before, after):
    """Files the run created or changed under the folder (temporary files left behind)."""
    return changed(before, after)


def outputs(suite, folder):
    """(name, command with OUT where the output path goes, exit code of a failed write)."""
    scene = os.path.join(folder, "scene.json")
    return [
        ("run --trace", [suite.cli, "run", scene, "--steps", "30", "--trace", "OUT"], 1),
        ("offscreen --screenshot", [suite.offscreen, scene, "--screenshot", "OUT"], 1),
        ("offscreen --layout-json", [suite.offscreen, scene, "--screenshot", "/dev/null",
                                     "--layout-json", "OUT"], 1),
        ("offscreen --text-json", [suite.offscreen, scene, "--screenshot", "/dev/null",
                                   "--text-json", "OUT"], 1),
        ("offscreen --audio-wav", [suite.offscreen, scene, "--frames", "10", "--audio-wav",
                                   "OUT"], 1),
    ]


def targets(folder):
    """(case, setup(folder) -> output path, the path whose old bytes must survive or None,
    run as nobody)."""
    def existing(name):
        def setup():
            path = os.path.join(folder, name)
            write(path, OLD)
            return path
        return setup

    def directory():
        os.makedirs(os.path.join(folder, "dir.out"), exist_ok=True)
        write(os.path.join(folder, "dir.out", "keep"), OLD)
        return os.path.join(folder, "dir.out")

    def under_file():
        write(os.path.join(folder, "plain"), OLD)
        return os.path.join(folder, "plain", "out")

    def read_only():
        ro = os.path.join(folder, "ro")
        os.makedirs(ro, exist_ok=True)
        write(os.path.join(ro, "out"), OLD)
        os.chmod(os.path.join(ro, "out"), 0o644)
        os.chmod(ro, 0o555)
        return os.path.join(ro, "out")

    def control_folder():
        return os.path.join(folder, "no\x1b[2Jsuch", "out")

    return [
        ("/dev/full", lambda: "/dev/full", None, False),
        ("a directory in the way", directory, os.path.join(folder, "dir.out", "keep"), False),
        ("under a regular file", under_file, os.path.join(folder, "plain"), False),
        ("a missing folder", lambda: os.path.join(folder, "missing", "out"), None, False),
        ("a control-byte folder", control_folder, None, False),
        ("a read-only folder", read_only, os.path.join(folder, "ro", "out"), True),
        ("a full disk over an old file", existing("full.out"), os.path.join(folder, "full.out"),
         False),
    ]


def run_cases(suite):
    base = suite.folder("writes")
    os.chmod(base, 0o777)
    write(os.path.join(base, "scene.json"), json.dumps(SCENE))
    os.chmod(os.path.join(base, "scene.json"), 0o644)
    for out_case, command, code in outputs(suite, base):
        for case, setup, keep, as_nobody in targets(base):
            name = "%s to %s" % (out_case, case)
            path = setup()
            old = read(keep) if keep else None
            before = snapshot(base)
            args = [path if a == "OUT" else a for a in command]
            fsize = FULL_DISK_BYTES if case.startswith("a full disk") else None
            result = run(args, base, timeout=300, mem_mb=2048, fsize=fsize,
                         as_nobody=as_nobody and os.geteuid() == 0)
            shown = os.path.basename(path) if "\x1b" not in path else "\\x1b"
            problems = suite.refused(result, [shown], code=code)
            if keep and read(keep) != old:
                problems.append("%s changed" % keep)
            extra = [p for p in leftovers(before, snapshot(base))
                     if not p.endswith("ok.png")]
            if extra:
                problems.append("left behind or changed: %s" % extra)
            if "ro" in path:
                os.chmod(os.path.dirname(path), 0o755)
            suite.check(name, problems, result)

    same_file_cases(suite)
    fifo_cases(suite)
    folder_outputs(suite)


def restore(kept, hard_links=()):
    """Puts back what a failed case overwrote (a file renamed over is written again), and the
    hard links (source, link) a rename has split."""
    for path, data in kept.items():
        if not os.path.isfile(path) or read(path) != data:
            write(path, data)
    for source, link in hard_links:
        if not os.path.samefile(source, link):
            os.remove(link)
            os.link(source, link)


def same_file_cases(suite):
    """An output that is an input: refused (run --trace: 1; offscreen outputs: 2), input intact."""
    folder = suite.folder("same file")
    scene = os.path.join(folder, "scene.json")
    write(scene, json.dumps(SCENE))
    os.mkdir(os.path.join(folder, "sub"))
    os.symlink("scene.json", os.path.join(folder, "link.csv"))
    os.link(scene, os.path.join(folder, "hard.csv"))
    lesson = os.path.join(folder, "lesson.json")
    write(lesson, json.dumps({"name": "L", "steps": [{"title": "t", "caption": "c",
                                                      "scene": "scene.json",
                                                      "pause_at": {"time": 0.1}}]}))
    trace = os.path.join(folder, "trace.csv")
    ok = run([suite.cli, "run", scene, "--steps", "20", "--trace", trace], folder)
    suite.check("write a trace to compare", suite.accepted(ok), ok)
    spellings = [("the same path", scene), ("./", "./scene.json"),
                 ("sub/..", "sub/../scene.json"), ("a symlink", "link.csv"),
                 ("a hard link", "hard.csv"), ("an absolute path", os.path.abspath(scene)),
                 ("a doubled slash", folder + "//scene.json")]
    kept = {p: read(p) for p in (scene, lesson, trace)}
    for how, out in spellings:
        cases = [
            ("run --trace", [suite.cli, "run", "scene.json", "--steps", "5", "--trace", out], 1),
            ("--screenshot", [suite.offscreen, "scene.json", "--screenshot", out], 2),
            ("--layout-json", [suite.offscreen, "scene.json", "--screenshot", "ok.png",
                               "--layout-json", out], 2),
            ("--text-json", [suite.offscreen, "scene.json", "--screenshot", "ok.png",
                             "--text-json", out], 2),
            ("--audio-wav", [suite.offscreen, "scene.json", "--frames", "5", "--audio-wav",
                             out], 2),
        ]
        for what, args, code in cases:
            restore(kept, [(scene, os.path.join(folder, "hard.csv"))])
            result = run(args, folder, timeout=300, mem_mb=2048)
            problems = suite.refused(result, [], code=code)
            for path, data in kept.items():
                if read(path) != data:
                    problems.append("%s changed" % os.path.basename(path))
            suite.check("%s onto the scene by %s" % (what, how), problems, result)
    others = [
        ("--screenshot onto the lesson",
         [suite.offscreen, "--lesson", "lesson.json", "--screenshot", "lesson.json"], 2),
        ("--screenshot onto the lesson's scene",
         [suite.offscreen, "--lesson", "lesson.json", "--screenshot", "sub/../scene.json"], 2),
        ("--screenshot onto the --compare trace",
         [suite.offscreen, "scene.json", "--compare", "trace.csv", "--screenshot", "trace.csv"],
         2),
        ("--layout-json onto the --compare trace",
         [suite.offscreen, "scene.json", "--compare", "trace.csv", "--screenshot", "ok.png",
          "--layout-json", "./trace.csv"], 2),
    ]
    for what, args, code in others:
        restore(kept, [(scene, os.path.join(folder, "hard.csv"))])
        result = run(args, folder, timeout=300, mem_mb=2048)
        problems = suite.refused(result, [], code=code)
        for path, data in kept.items():
            if read(path) != data:
                problems.append("%s changed" % os.path.basename(path))
        suite.check(what, problems, result)


def fifo_cases(suite):
    """A FIFO nobody reads: an error at once, not a hang. /dev/null: written in place."""
    folder = suite.folder("fifo")
    write(os.path.join(folder, "scene.json"), json.dumps(SCENE))
    os.mkfifo(os.path.join(folder, "pipe"))
    for what, args in [
            ("run --trace", [suite.cli, "run", "scene.json", "--steps", "5", "--trace", "pipe"]),
            ("--screenshot", [suite.offscreen, "scene.json", "--screenshot", "pipe"]),
            ("--layout-json", [suite.offscreen, "scene.json", "--screenshot", "ok.png",
                               "--layout-json", "pipe"])]:
        result = run(args, folder, timeout=120, mem_mb=2048)
        suite.check("%s to a FIFO nobody reads" % what, suite.refused(result, ["pipe"]), result)
    for what, args in [
            ("run --trace", [suite.cli, "run", "scene.json", "--steps", "5", "--trace",
                             "/dev/null"]),
            ("--screenshot", [suite.offscreen, "scene.json", "--screenshot", "/dev/null"])]:
        result = run(args, folder, timeout=300, mem_mb=2048)
        problems = suite.accepted(result)
        if not os.path.exists("/dev/null") or not os.path.isfile(os.path.join(folder,
                                                                               "scene.json")):
            problems.append("/dev/null or the scene is gone")
        suite.check("%s to /dev/null" % what, problems, result)


def folder_outputs(suite):
    """Commands that write into a folder: a folder that cannot be, or a full disk inside it."""
    folder = suite.folder("folders")
    write(os.path.join(folder, "afile"), OLD)
    write(os.path.join(folder, "scene.json"), json.dumps(SCENE))
    os.makedirs(os.path.join(folder, "stab", "stability.csv"))
    os.makedirs(os.path.join(folder, "full"))
    write(os.path.join(folder, "full", "stability.csv"), OLD)
    scenes = os.path.join(suite.source, "app", "scenes")
    cases = [
        ("stability --out a regular file",
         [suite.cli, "stability", "--out", "afile", "--scenes", scenes], ["afile"], None),
        ("stability --out /dev/full", [suite.cli, "stability", "--out", "/dev/full", "--scenes",
                                       scenes], ["/dev/full"], None),
        ("stability --out with a directory in the way",
         [suite.cli, "stability", "--out", "stab", "--scenes", scenes], ["stability.csv"], None),
        ("stability --out on a full disk",
         [suite.cli, "stability", "--out", "full", "--scenes", scenes], ["stability"], 2048),
        ("stability --scenes a missing folder",
         [suite.cli, "stability", "--out", "o", "--scenes", "nope"], ["nope"], None),
        ("tradeoff --out a regular file",
         [suite.cli, "tradeoff", "--out", "afile", "--quick"], ["afile"], None),
        ("offscreen --record into a regular file",
         [suite.offscreen, "scene.json", "--frames", "3", "--record", "afile"], ["afile"], None),
        ("offscreen --record into /dev/full",
         [suite.offscreen, "scene.json", "--frames", "3", "--record", "/dev/full"],
         ["/dev/full"], None),
        ("offscreen --record-steps into a regular file",
         [suite.offscreen, "--lesson", "lecture3", "--record-steps", "afile"], ["afile"], None),
    ]
    for what, args, places, fsize in cases:
        before = {p: read(p) for p in (os.path.join(folder, "afile"),
                                       os.path.join(folder, "full", "stability.csv"))}
        result = run(args, folder, timeout=300, mem_mb=2048, fsize=fsize)
        problems = suite.refused(result, places, code=1)
        for path, data in before.items():
            if read(path) != data:
                problems.append("%s changed" % path)
        suite.check(what, problems, result)
