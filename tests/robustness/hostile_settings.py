"""The window's settings file as hostile input (issue 28, "The settings file is input too"), from
the README ("Saving": settings in $XDG_CONFIG_HOME/collision-sandbox/settings.txt, or under
~/.config; a bad file never stops the start; warnings `FILE:LINE: ...`; a file that is not
regular or larger than 1 MiB gives the defaults; on exit the file is rewritten whole, nothing
written outside its folder). Each case starts `sandbox --verbose` on an X server (run the class
under xvfb-run), waits for its first frame ("window ready"), quits with Ctrl+Q and checks: exit
0, the warnings, the file repaired, and nothing outside the settings folder changed."""
import json
import os
import re
import shutil

from hostile_outside import NOBODY, changed, read, run, snapshot, write

# Starts the window, waits for its first frame, sends Ctrl+Q, exits with the window's code.
# A window that never shows is stopped by the suite's timeout (a hang fails the case).
DRIVER = r'''
out=$1; shift
: >"$out"  # there before the first grep (the background job's redirection may come later)
"$@" >"$out" &
pid=$!
until grep -q "window ready" "$out"; do
    kill -0 "$pid" 2>/dev/null || { wait "$pid"; exit $?; }
    sleep 0.1
done
wid=$(xdotool search --sync --pid "$pid" --name "Collision sandbox" | head -n 1)
xdotool windowfocus --sync "$wid" key --clearmodifiers ctrl+q
wait "$pid"
'''

SCENE = {"name": "one", "world": {"gravity": [0, 0]},
         "blocks": [{"name": "a", "position": [4, 6], "size": 1}]}
RANGES = {"ui_scale": (0.75, 3), "label_scale": (0.75, 2.5), "volume": (0, 1),
          "window_width": (16, 16384), "window_height": (16, 16384)}


def repaired(text):
    """Problems with a settings file as the app rewrote it: every line `key = value`, numbers
    finite and in range, last_scene absolute."""
    problems = []
    for n, line in enumerate(text.splitlines(), 1):
        if line.startswith("#"):
            continue
        m = re.fullmatch(r"([a-z_]+) = (.*)", line)
        if not m:
            problems.append("rewritten settings line %d is not key = value: %r" % (n, line[:80]))
            continue
        key, value = m.groups()
        if key in RANGES:
            try:
                number = float(value)
            except ValueError:
                problems.append("rewritten %s is not a number: %r" % (key, value[:80]))
                continue
            low, high = RANGES[key]
            if not low <= number <= high:
                problems.append("rewritten %s = %s is out of range" % (key, value))
        if key == "last_scene" and value and not value.startswith("/"):
            problems.append("rewritten last_scene is not absolute: %r" % value[:80])
    return problems


class Case:
    def __init__(self, suite, name):
        self.suite, self.name = suite, name
        self.folder = suite.folder("settings " + name)
        self.xdg = os.path.join(self.folder, "xdg")
        self.dir = os.path.join(self.xdg, "collision-sandbox")
        self.file = os.path.join(self.dir, "settings.txt")
        os.makedirs(self.dir, exist_ok=True)
        self.env = dict(os.environ, XDG_CONFIG_HOME=self.xdg, HOME=os.path.join(self.folder, "h"))

    def start(self, args=(), as_nobody=False, outside=()):
        """Runs the window to its first frame and quits; returns (result, problems)."""
        out = os.path.join(self.folder, "window.out")
        before = snapshot(self.folder)
        outside_before = {p: read(p) for p in outside}
        env = dict(self.env)
        if as_nobody:
            for path in (self.folder,):
                os.chmod(path, 0o777)
            if "XAUTHORITY" in env:
                auth = os.path.join(self.folder, "xauth")
                shutil.copy(env["XAUTHORITY"], auth)
                os.chown(auth, NOBODY, NOBODY)
                env["XAUTHORITY"] = auth
        result = run(["sh", "-c", DRIVER, "driver", out, self.suite.window, "--verbose"] +
                     list(args), self.folder, timeout=180, mem_mb=4096, env=env,
                     as_nobody=as_nobody)
        result.out = read(out) if os.path.exists(out) else b""
        problems = self.suite.common(result)
        if result.code != 0:
            problems.append("exit %d: the app did not start and quit" % result.code)
        if b"window ready" not in result.out:
            problems.append("no first frame")
        after = snapshot(self.folder)
        settings_dir = self.dir + os.sep
        moved = [p for p in changed(before, after)
                 if not (p + os.sep).startswith(settings_dir) and
                 not p.endswith(("window.out", "xauth"))]
        if moved:
            problems.append("written outside the settings folder: %s" % moved)
        for path, data in outside_before.items():
            if read(path) != data:
                problems.append("%s changed" % path)
        return result, problems

    def file_problems(self):
        if not os.path.isfile(self.file) or os.path.islink(self.file):
            return ["settings.txt is not a regular file after the save"]
        return repaired(read(self.file).decode("utf-8", "replace"))


def warns(result, *places):
    return ["no warning naming %r" % p for p in places if p.encode() not in result.err]


def run_cases(suite):
    if not os.environ.get("DISPLAY"):
        suite.check("an X server (run under xvfb-run)", ["DISPLAY is not set"])
        return
    scene = os.path.join(suite.root, "good.json")
    write(scene, json.dumps(SCENE))
    bad_scene = os.path.join(suite.root, "bad.json")
    write(bad_scene, json.dumps(dict(SCENE, blocks=[dict(SCENE["blocks"][0], mass="heavy")])))
    fifo = os.path.join(suite.root, "fifo.json")
    os.mkfifo(fifo)
    os.mkdir(os.path.join(suite.root, "dir.json"))
    os.symlink("loop.json", os.path.join(suite.root, "loop.json"))
    outside = os.path.join(suite.root, "outside.txt")
    write(outside, "ui_scale = 2\n")

    def file_case(name, text, places=(), must_repair=True):
        case = Case(suite, name)
        write(case.file, text)
        result, problems = case.start()
        problems += warns(result, *places)
        if must_repair:
            problems += case.file_problems()
        suite.check("settings: " + name, problems, result)
        return case, result

    case = Case(suite, "first launch")
    result, problems = case.start()
    suite.check("settings: first launch", problems + case.file_problems(), result)
    written = read(case.file).decode() if os.path.isfile(case.file) else ""
    keys = re.findall(r"^([a-z_]+) = ", written, re.M)
    for key in ("ui_scale", "window_width", "window_height"):
        if key not in keys:
            suite.check("settings: the file has %s" % key, ["%s not in %r" % (key, written)])

    file_case("binary garbage", bytes(range(256)) * 16, ["settings.txt:"])
    file_case("a line without =", "ui_scale 2\n", ["settings.txt:1"])
    file_case("an unknown key", "ui_scale = 1\nsparkles = 3\n", ["settings.txt:2"])
    file_case("NaN spelled six ways",
              "ui_scale = nan\nlabel_scale = -nan\nvolume = NaN\nwindow_width = inf\n"
              "window_height = 1e999\nlight_theme = nan\n",
              ["settings.txt:%d" % n for n in range(1, 7)])
    file_case("hex and trailing text", "ui_scale = 0x2\nwindow_width = 800px\n",
              ["settings.txt:1", "settings.txt:2"])
    file_case("out of range", "ui_scale = 1000\nwindow_width = 99999999999\nvolume = -5\n"
              "label_scale = 1e-300\nwindow_height = -1\n",
              ["settings.txt:%d" % n for n in range(1, 6)])
    file_case("larger than 1 MiB", "ui_scale = 1\n" * 100000, ["settings.txt"])
    case, result = file_case("one 900 kB line", "ui_scale = " + "9" * 900000, ["settings.txt:1"])
    file_case("50,000 bad lines", "bad line\n" * 50000, ["settings.txt:1"])
    file_case("escape bytes in a key and a value",
              "\x1b]0;owned\x07 = 1\nui_scale = \x1b[2J\n", ["settings.txt:1", "\\x1b"])
    file_case("CRLF and a BOM", "\ufeffui_scale = 1.5\r\nlight_theme = 1\r\n")
    file_case("last scene /dev/zero", "last_scene = /dev/zero\n", ["settings.txt:1"])
    file_case("last scene /dev/stdin", "last_scene = /dev/stdin\n", ["settings.txt:1"])
    file_case("last scene a FIFO", "last_scene = %s\n" % fifo, ["settings.txt:1"])
    file_case("last scene a directory", "last_scene = %s\n" % os.path.join(suite.root,
                                                                          "dir.json"),
              ["settings.txt:1"])
    file_case("last scene gone", "ui_scale = 1\nlast_scene = /no/such/scene.json\n",
              ["settings.txt:2"])
    file_case("last scene relative", "last_scene = good.json\n", ["settings.txt:1"])
    file_case("last scene a link loop", "last_scene = %s\n" % os.path.join(suite.root,
                                                                          "loop.json"),
              ["settings.txt:1", "is a loop of symbolic links"])
    file_case("last scene a control-byte path", "last_scene = /no/\x1b[31mx.json\n",
              ["settings.txt:1", "\\x1b"])
    file_case("last scene a bad scene file", "last_scene = %s\n" % bad_scene, ["bad.json"])
    case, result = file_case("last scene a good scene", "last_scene = %s\n" % scene)
    if result.err.strip():
        suite.check("settings: a good last scene gives no warning", ["stderr: %r" % result.err])

    def kind_case(name, make, check_file=True, outside_files=()):
        case = Case(suite, name)
        make(case)
        result, problems = case.start(outside=outside_files)
        if check_file:
            problems += case.file_problems()
        suite.check("settings: " + name, problems, result)

    kind_case("the file a FIFO", lambda c: os.mkfifo(c.file))
    kind_case("the file a link to /dev/zero", lambda c: os.symlink("/dev/zero", c.file))
    kind_case("the file a link to /dev/urandom", lambda c: os.symlink("/dev/urandom", c.file))
    kind_case("the file a link outside the folder", lambda c: os.symlink(outside, c.file),
              check_file=False, outside_files=[outside])
    kind_case("the file a directory", lambda c: os.mkdir(c.file), check_file=False)
    kind_case("the file a link loop", lambda c: os.symlink("settings.txt", c.file))

    def folder_is_file(case):
        os.rmdir(case.dir)
        write(case.dir, "not a folder\n")
    case = Case(suite, "the folder a file")
    folder_is_file(case)
    result, problems = case.start()
    if read(case.dir) != b"not a folder\n":
        problems.append("the file in the folder's place changed")
    suite.check("settings: the settings folder is a file", problems, result)

    if os.geteuid() == 0:  # permissions bind nobody, not root
        case = Case(suite, "unreadable")
        write(case.file, "ui_scale = 2\n")
        os.chmod(case.file, 0)
        for path in (case.xdg, case.dir):
            os.chmod(path, 0o777)
        result, problems = case.start(as_nobody=True)
        problems += warns(result, "settings.txt")
        suite.check("settings: the file unreadable", problems, result)

    case = Case(suite, "HOME only")
    case.env.pop("XDG_CONFIG_HOME")
    result, problems = case.start()
    home_file = os.path.join(case.folder, "h", ".config", "collision-sandbox", "settings.txt")
    if not os.path.isfile(home_file):
        problems.append("no settings under $HOME/.config")
    # The HOME folder is where the settings go here, so "outside" is the rest of the case.
    problems = [p for p in problems if not p.startswith("written outside")]
    suite.check("settings: found through HOME", problems, result)

    # A bad lesson at the window's start: refused with its place, exit 1.
    case = Case(suite, "bad lesson")
    lesson = os.path.join(case.folder, "lesson.json")
    write(lesson, json.dumps({"name": "L", "steps": [{"title": "t", "caption": "c",
                                                      "scene": "/dev/zero"}]}))
    result = run([suite.window, "--lesson", lesson], case.folder, timeout=180, mem_mb=4096,
                 env=case.env)
    suite.check("window: a lesson naming /dev/zero", suite.refused(
        result, ["lesson.json", "steps[0].scene"], code=1), result)
