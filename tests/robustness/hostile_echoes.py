"""Paths echoed by every command (issue 41), from docs/cli.md, "Echoed text is safe": a folder
whose name holds ESC, an OSC title sequence, a BEL and a CSI colour is given to every option that
writes a file or a folder, and every file a command reads is put there too. Whatever a command
prints about those paths (the files it wrote, its errors) shows the bytes escaped (\\x1b, \\x07),
never raw, on stdout and on stderr, on success and on failure."""
import json
import os

from hostile_outside import run, write

# ESC ] 0 ; title BEL (sets a terminal's title), ESC [ 31 m (red), a C1 CSI, a right-to-left mark.
HOSTILE = "out\x1b]0;owned\x07\x1b[31mred\xc2\x9b2J\u202eevil"
ESCAPED = "\\x1b]0;owned\\x07"  # how printable() shows the start of it

SCENE = {"name": "two", "duration": 0.5, "world": {"gravity": [0, 0]},
         "blocks": [{"name": "m1", "position": [4, 6], "size": 1, "velocity": [6, 0]},
                    {"name": "m2", "position": [10, 6], "size": 1.5, "mass": 2}]}
LESSON = {"name": "one step", "steps": [{"title": "two blocks", "caption": "they meet",
                                         "scene": "scene.json",
                                         "pause_at": {"time": 0.2}}]}


def hostile_folder(suite, case):
    """A case's folder with the hostile folder inside it, holding the scene and the lesson."""
    folder = os.path.join(suite.folder(case), HOSTILE)
    os.makedirs(folder, exist_ok=True)
    write(os.path.join(folder, "scene.json"), json.dumps(SCENE))
    write(os.path.join(folder, "lesson.json"), json.dumps(LESSON))
    write(os.path.join(folder, "bad.json"), '{"name": "bad", "blocks": [ oops')
    write(os.path.join(folder, "trace.csv"), "t,m1_x,m1_y,m1_vx,m1_vy\n0.1,abc,6,6,0\n")
    write(os.path.join(folder, "a file"), "in the way\n")
    return folder


def escaped_echo(suite, result, named, stream="out"):
    """Problems: raw control bytes anywhere, and `named` (the hostile folder) not shown escaped
    on `stream` ("out" or "err")."""
    problems = suite.common(result, echo_stdout=True)
    text = result.out if stream == "out" else result.err
    if named and ESCAPED.encode() not in text:
        problems.append("std%s does not show the folder's name escaped (%r)" % (stream, ESCAPED))
    return problems


def run_cases(suite):
    def wrote(case, args, stream="out", expect_ok=True, timeout=300):
        """A command run with the hostile folder in `args` (HERE stands for it)."""
        folder = hostile_folder(suite, case)
        args = [a.replace("HERE", folder) if isinstance(a, str) else a for a in args]
        result = run(args, cwd=os.path.dirname(folder), timeout=timeout, mem_mb=3072)
        problems = escaped_echo(suite, result, True, stream)
        if expect_ok and result.code != 0:
            problems.append("exit %d" % result.code)
        if not expect_ok and result.code == 0:
            problems.append("exit 0 on a failure")
        suite.check(case, problems, result)

    cli, offscreen = suite.cli, suite.offscreen
    # What the commands wrote, on stdout.
    wrote("stability --out", [cli, "stability", "--out", "HERE/matrix", "--extremes", ""])
    wrote("tradeoff --out", [cli, "tradeoff", "--out", "HERE/chart", "--quick"])
    wrote("offscreen --screenshot", [offscreen, "HERE/scene.json", "--screenshot", "HERE/s.png"])
    wrote("offscreen --record", [offscreen, "HERE/scene.json", "--frames", "2", "--size",
                                 "320x200", "--record", "HERE/frames"])
    wrote("offscreen --record-steps", [offscreen, "--lesson", "HERE/lesson.json", "--size",
                                       "320x200", "--record-steps", "HERE/steps"])
    wrote("offscreen --audio-wav", [offscreen, "HERE/scene.json", "--frames", "30",
                                    "--audio-wav", "HERE/knock.wav"])
    # What could not be written or read, on stderr.
    wrote("stability --out under a file", [cli, "stability", "--out", "HERE/a file/x",
                                           "--extremes", ""], "err", False)
    wrote("tradeoff --out under a file", [cli, "tradeoff", "--out", "HERE/a file/x", "--quick"],
          "err", False)
    wrote("run --trace under a file", [cli, "run", "HERE/scene.json", "--steps", "3", "--trace",
                                       "HERE/a file/t.csv"], "err", False)
    wrote("offscreen --screenshot under a file", [offscreen, "HERE/scene.json", "--screenshot",
                                                  "HERE/a file/s.png"], "err", False)
    wrote("offscreen --record under a file", [offscreen, "HERE/scene.json", "--frames", "2",
                                              "--record", "HERE/a file/frames"], "err", False)
    wrote("offscreen --layout-json under a file", [offscreen, "HERE/scene.json", "--screenshot",
                                                   "HERE/s.png", "--layout-json",
                                                   "HERE/a file/l.json"], "err", False)
    wrote("offscreen --audio-wav under a file", [offscreen, "HERE/scene.json", "--frames", "3",
                                                 "--audio-wav", "HERE/a file/k.wav"], "err", False)
    wrote("stability --scenes missing", [cli, "stability", "--out", "HERE/m", "--scenes",
                                         "HERE/none"], "err", False)
    wrote("run a bad scene", [cli, "run", "HERE/bad.json"], "err", False)
    wrote("validate a bad scene", [cli, "validate", "HERE/bad.json"], "err", False)
    wrote("lesson a bad lesson", [cli, "lesson", "HERE/bad.json"], "err", False)
    wrote("compare a bad trace", [cli, "compare", "HERE/scene.json", "HERE/trace.csv"], "err",
          False)
    wrote("offscreen a missing scene", [offscreen, "HERE/missing.json", "--screenshot",
                                        "HERE/s.png"], "err", False)
