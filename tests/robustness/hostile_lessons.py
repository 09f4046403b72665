"""Lesson files as hostile input (issue 28, "Lessons are input like scenes"), from
docs/lesson-format.md: every key, type, range and path, scenes inline and by path, syntax, sizes
and echoed names. Each bad lesson is refused by `sandbox-cli validate`, `sandbox-cli lesson` and
`sandbox-offscreen --lesson` with exit 1 and its place on stderr."""
import copy
import json
import os
import re

from hostile_outside import read, run, write

SCENE = {"name": "two", "world": {"gravity": [0, 0]},
         "blocks": [{"name": "a", "position": [4, 6], "size": 1, "velocity": [2, 0]},
                    {"name": "b", "position": [10, 6], "size": 1}]}
PLAYER_SCENE = {"name": "player", "blocks": [{"name": "p", "position": [4, 1], "size": 1}],
                "player": {"block": "p", "force": 20, "jump": 5}}


def lesson(step=None, top=None, scene=None):
    """A valid one-step lesson with step keys and top-level keys replaced (None deletes)."""
    s = {"title": "t", "caption": "c", "scene": copy.deepcopy(SCENE if scene is None else scene),
         "pause_at": {"time": 1}}
    doc = {"name": "L", "steps": [s]}
    for target, patch in ((s, step), (doc, top)):
        for key, value in (patch or {}).items():
            if value is None:
                target.pop(key, None)
            else:
                target[key] = value
    return doc


# Two choices for a question about the lesson() step (a time of 1 s): the first is proved.
CHOICES = [{"text": "{a.vx0} m/s", "if": "a.vx == a.vx0", "correct": True},
           {"text": "0 m/s", "if": "a.vx == 0"}]


def asking(**step):
    """lesson() with a question, choices and an answer, and `step` on top."""
    base = {"question": "How fast is a?", "answer": "{a.vx} m/s", "choices": CHOICES}
    base.update(step)
    return lesson(step=base)


LONG = "x" * 201
ESC_NAME = "\x1b]0;owned\x07\x1b[31mred"

# (case, lesson document, places that the error names). The file is always lesson.json.
KEY_CASES = [
    ("top unknown key", lesson(top={"bogus": 1}), ["bogus"]),
    ("name missing", lesson(top={"name": None}), ["name"]),
    ("name a number", lesson(top={"name": 3}), ["name"]),
    ("name two lines", lesson(top={"name": "a\nb"}), ["name"]),
    ("description a number", lesson(top={"description": 1}), ["description"]),
    ("steps missing", lesson(top={"steps": None}), ["steps"]),
    ("steps empty", lesson(top={"steps": []}), ["steps"]),
    ("steps an object", lesson(top={"steps": {}}), ["steps"]),
    ("steps 1001", {"name": "L", "steps": [lesson()["steps"][0]] * 1001}, ["steps"]),
    ("step not an object", lesson(top={"steps": [3]}), ["steps[0]"]),
    ("step unknown key", lesson(step={"sparkle": True}), ["steps[0]", "sparkle"]),
    ("title missing", lesson(step={"title": None}), ["steps[0]", "title"]),
    ("title too long", lesson(step={"title": LONG}), ["steps[0].title"]),
    ("title two lines", lesson(step={"title": "a\nb"}), ["steps[0].title"]),
    ("caption missing", lesson(step={"caption": None}), ["steps[0]", "caption"]),
    ("caption four lines", lesson(step={"caption": "a\nb\nc\nd"}), ["steps[0].caption"]),
    ("caption line too long", lesson(step={"caption": "a\n" + LONG}), ["steps[0].caption"]),
    ("scene missing", lesson(step={"scene": None}), ["steps[0]", "scene"]),
    ("scene a number", lesson(step={"scene": 7}), ["steps[0].scene"]),
    ("scene an array", lesson(step={"scene": []}), ["steps[0].scene"]),
    ("scene unknown shipped name", lesson(step={"scene": "no_such_scene"}), ["steps[0].scene"]),
    ("inline scene bad mass",
     lesson(step={"scene": dict(SCENE, blocks=[dict(SCENE["blocks"][0], mass=-1)])}),
     ["steps[0].scene.blocks[0].mass"]),
    ("inline scene unknown key", lesson(step={"scene": dict(SCENE, bogus=1)}),
     ["steps[0].scene", "bogus"]),
    ("inline scene overlap",
     lesson(step={"scene": dict(SCENE, blocks=[SCENE["blocks"][0], SCENE["blocks"][0]])}),
     ["steps[0].scene.blocks"]),
    ("overrides unknown key", lesson(step={"overrides": {"bogus": 1}}),
     ["steps[0].overrides", "bogus"]),
    ("overrides bounciness 2", lesson(step={"overrides": {"bounciness": 2}}),
     ["steps[0].overrides.bounciness"]),
    ("overrides dt 0", lesson(step={"overrides": {"dt": 0}}), ["steps[0].overrides.dt"]),
    ("overrides substeps 1001", lesson(step={"overrides": {"substeps": 1001}}),
     ["steps[0].overrides.substeps"]),
    ("overrides method unknown", lesson(step={"overrides": {"method": "magic"}}),
     ["steps[0].overrides.method"]),
    ("overrides gravity 1e10", lesson(step={"overrides": {"gravity": [0, 1e10]}}),
     ["steps[0].overrides.gravity"]),
    ("overrides bounds inverted", lesson(step={"overrides": {"bounds": [20, 0, 0, 12]}}),
     ["steps[0].overrides.bounds"]),
    ("overrides mistakes twice",
     lesson(step={"overrides": {"mistakes": ["discrete", "discrete"]}}),
     ["steps[0].overrides.mistakes"]),
    ("overrides frame_rate 0", lesson(step={"overrides": {"frame_rate": 0}}),
     ["steps[0].overrides.frame_rate"]),
    ("overrides frame_rate 10001", lesson(step={"overrides": {"frame_rate": 10001}}),
     ["steps[0].overrides.frame_rate"]),
    ("overrides dt and frame_rate", lesson(step={"overrides": {"dt": 0.01, "frame_rate": 60}}),
     ["steps[0].overrides"]),
    ("overrides time_scale 0.001", lesson(step={"overrides": {"time_scale": 0.001}}),
     ["steps[0].overrides.time_scale"]),
    ("overrides time_scale a string", lesson(step={"overrides": {"time_scale": "fast"}}),
     ["steps[0].overrides.time_scale"]),
    ("overlays unknown", lesson(step={"overlays": ["sparkles"]}), ["steps[0].overlays[0]"]),
    ("overlays not an array", lesson(step={"overlays": "trails"}), ["steps[0].overlays"]),
    ("overlays a number inside", lesson(step={"overlays": ["trails", 3]}),
     ["steps[0].overlays[1]"]),
    ("select no such block", lesson(step={"select": "zz"}), ["steps[0].select"]),
    ("select a number", lesson(step={"select": 1}), ["steps[0].select"]),
    ("thrust without select", lesson(step={"thrust": 10}), ["steps[0].thrust"]),
    ("thrust 0", lesson(step={"select": "a", "thrust": 0}), ["steps[0].thrust"]),
    ("thrust 1e5", lesson(step={"select": "a", "thrust": 1e5}), ["steps[0].thrust"]),
    ("thrust on a static block",
     lesson(step={"select": "s", "thrust": 10,
                  "scene": dict(SCENE, blocks=SCENE["blocks"] + [
                      {"name": "s", "position": [15, 2], "size": 1, "mass": "static"}])}),
     ["steps[0].thrust"]),
    ("input without player", lesson(step={"input": [{"at": 0, "press": "up"}]}),
     ["steps[0].input"]),
    ("input unknown key", lesson(scene=PLAYER_SCENE, step={"input": [{"at": 0, "press": "jump"}]}),
     ["steps[0].input[0].press"]),
    ("input hold and press",
     lesson(scene=PLAYER_SCENE,
            step={"input": [{"at": 0, "press": "up", "hold": ["left"], "for": 1}]}),
     ["steps[0].input[0]"]),
    ("input hold without for", lesson(scene=PLAYER_SCENE,
                                      step={"input": [{"at": 0, "hold": ["left"]}]}),
     ["steps[0].input[0]"]),
    ("input press with for", lesson(scene=PLAYER_SCENE,
                                    step={"input": [{"at": 0, "press": "up", "for": 1}]}),
     ["steps[0].input[0]"]),
    ("input at 601", lesson(scene=PLAYER_SCENE, step={"input": [{"at": 601, "press": "up"}]}),
     ["steps[0].input[0].at"]),
    ("input for 0", lesson(scene=PLAYER_SCENE,
                           step={"input": [{"at": 0, "hold": ["up"], "for": 0}]}),
     ["steps[0].input[0].for"]),
    ("input hold four keys",
     lesson(scene=PLAYER_SCENE,
            step={"input": [{"at": 0, "hold": ["left", "right", "up", "up"], "for": 1}]}),
     ["steps[0].input[0].hold"]),
    ("input hold empty", lesson(scene=PLAYER_SCENE,
                                step={"input": [{"at": 0, "hold": [], "for": 1}]}),
     ["steps[0].input[0].hold"]),
    ("camera three numbers", lesson(step={"camera": [0, 0, 1]}), ["steps[0].camera"]),
    ("camera inverted", lesson(step={"camera": [10, 0, 0, 10]}), ["steps[0].camera"]),
    ("camera 1e300", lesson(step={"camera": [0, 0, 1e300, 1]}), ["steps[0].camera"]),
    ("frame moon", lesson(step={"frame": "moon"}), ["steps[0].frame"]),
    ("pause_at two keys", lesson(step={"pause_at": {"time": 1, "collision": 1}}),
     ["steps[0].pause_at"]),
    ("pause_at empty", lesson(step={"pause_at": {}}), ["steps[0].pause_at"]),
    ("pause_at time -1", lesson(step={"pause_at": {"time": -1}}), ["steps[0].pause_at.time"]),
    ("pause_at time 601", lesson(step={"pause_at": {"time": 601}}), ["steps[0].pause_at.time"]),
    ("pause_at collision 0", lesson(step={"pause_at": {"collision": 0}}),
     ["steps[0].pause_at.collision"]),
    ("pause_at collision 1.5", lesson(step={"pause_at": {"collision": 1.5}}),
     ["steps[0].pause_at.collision"]),
    ("pause_at collision 1e300", lesson(step={"pause_at": {"collision": 1e300}}),
     ["steps[0].pause_at.collision"]),
    ("pause_at unknown block", lesson(step={"pause_at": {"first_collision_of": "zz"}}),
     ["steps[0].pause_at.first_collision_of"]),
    ("question without answer", lesson(step={"question": "q?"}), ["steps[0]"]),
    ("given without question", lesson(step={"given": [{"time": 0}]}), ["steps[0].given"]),
    ("reveal unknown overlay", lesson(step={"question": "q", "answer": "a", "choices": CHOICES,
                                            "reveal": ["sparkles"]}), ["steps[0].reveal[0]"]),
    ("question without choices", lesson(step={"question": "q", "answer": "a"}), ["steps[0]"]),
    ("choices without question", lesson(step={"choices": CHOICES}), ["steps[0].choices"]),
    ("one choice", asking(choices=CHOICES[:1]), ["steps[0].choices"]),
    ("five choices", asking(choices=CHOICES * 3), ["steps[0].choices"]),
    ("no correct choice", asking(choices=[{"text": "x", "if": "t > 0"}] * 2),
     ["steps[0].choices"]),
    ("two correct choices", asking(choices=[CHOICES[0], CHOICES[0]]),
     ["steps[0].choices[1].correct"]),
    ("choice without if", asking(choices=[{"text": "x", "correct": True}, CHOICES[1]]),
     ["steps[0].choices[0]"]),
    ("choice correct a string", asking(choices=[dict(CHOICES[0], correct="yes"), CHOICES[1]]),
     ["steps[0].choices[0].correct"]),
    ("choice if a number", asking(choices=[dict(CHOICES[0], **{"if": "a.vx + 1"}), CHOICES[1]]),
     ["steps[0].choices[0].if", "column"]),
    ("choice text a condition", asking(choices=[dict(CHOICES[0], text="{a.vx > 1}"), CHOICES[1]]),
     ["steps[0].choices[0].text", "column"]),
    ("unknown block in an answer", asking(answer="{zz.vx}"), ["steps[0].answer", "column 2"]),
    ("unknown quantity", asking(answer="{a.colour}"), ["steps[0].answer", "column 4"]),
    ("unknown name", asking(answer="{v}"), ["steps[0].answer", "column 2"]),
    ("unknown hit number", asking(answer="{hit.q}"), ["steps[0].answer", "column"]),
    ("an unclosed brace", asking(answer="v = {a.vx"), ["steps[0].answer", "column 5"]),
    ("a stray closing brace", asking(answer="v = }"), ["steps[0].answer", "column 5"]),
    ("an empty expression", asking(answer="{ }"), ["steps[0].answer"]),
    ("an unclosed quote", asking(answer="{'a.vx}"), ["steps[0].answer"]),
    ("a bad number", asking(answer="{1.2.3}"), ["steps[0].answer"]),
    ("a missing operand", asking(answer="{a.vx * }"), ["steps[0].answer"]),
    ("deep parentheses", asking(answer="{" + "(" * 190 + "1" + ")" * 190 + "}"),
     ["steps[0].answer", "nested too deeply"]),
    ("deep minus signs", asking(answer="{" + "-" * 380 + "1}"), ["steps[0].answer", "nested"]),
    ("a template line of 401", asking(answer="{" + "+".join(["1"] * 200) + "}"),
     ["steps[0].answer", "400"]),
    ("value reads itself", asking(values={"u": "w + 1", "w": "u * 2"}), ["steps[0].values"]),
    ("value named C", asking(values={"C": "1"}), ["steps[0].values.C"]),
    ("value named 2x", asking(values={"2x": "1"}), ["steps[0].values"]),
    ("value not a string", asking(values={"u": 1}), ["steps[0].values.u"]),
    ("values an array", asking(values=["u"]), ["steps[0].values"]),
    ("21 values", asking(values={"v%d" % i: "1" for i in range(21)}), ["steps[0].values"]),
    ("collision_of one block twice", lesson(step={"pause_at": {"collision_of": ["a", "a"]}}),
     ["steps[0].pause_at.collision_of"]),
    ("collision_of three", lesson(step={"pause_at": {"collision_of": ["a", "b", "a"]}}),
     ["steps[0].pause_at.collision_of"]),
    ("collision_of unknown", lesson(step={"pause_at": {"collision_of": ["a", "zz"]}}),
     ["steps[0].pause_at.collision_of[1]"]),
    ("rest unknown", lesson(step={"pause_at": {"rest": "zz"}}), ["steps[0].pause_at.rest"]),
    ("reach without a place", lesson(step={"pause_at": {"reach": "a"}}), ["steps[0].pause_at"]),
    ("reach two places", lesson(step={"pause_at": {"reach": "a", "x": {"min": 1},
                                                   "y": {"min": 1}}}), ["steps[0].pause_at"]),
    ("reach min and max", lesson(step={"pause_at": {"reach": "a", "x": {"min": 1, "max": 2}}}),
     ["steps[0].pause_at.x"]),
    ("a place without reach", lesson(step={"pause_at": {"rest": "a", "x": {"min": 1}}}),
     ["steps[0].pause_at.x"]),
    ("watch 0.5", lesson(step={"pause_at": {"rest": "a", "watch": 0.5}}),
     ["steps[0].pause_at.watch"]),
    ("watch with a time", lesson(step={"pause_at": {"time": 1, "watch": 2}}),
     ["steps[0].pause_at.watch"]),
    ("within 0", lesson(step={"pause_at": {"rest": "a", "within": 0}}),
     ["steps[0].pause_at.within"]),
    ("within 601", lesson(step={"pause_at": {"rest": "a", "within": 601}}),
     ["steps[0].pause_at.within"]),
    ("marked choice contradicted",
     asking(choices=[dict(CHOICES[1], correct=True), {"text": "a", "if": "a.vx == a.vx0"}]),
     ["steps[0].choices[0]", "contradicts"]),
    ("a second choice proved too", asking(choices=[CHOICES[0], {"text": "y", "if": "t >= 0"}]),
     ["steps[0].choices[1]", "proves it too"]),
    ("expect not an array", lesson(step={"expect": {"time": 1}}), ["steps[0].expect"]),
    ("expect unknown key", lesson(step={"expect": [{"colour": 1}]}), ["steps[0].expect[0]"]),
    ("expect no such block", lesson(step={"expect": [{"block": "zz", "x": 1}]}),
     ["steps[0].expect[0].block"]),
    ("expect x without block", lesson(step={"expect": [{"x": 1}]}), ["steps[0].expect[0]"]),
    ("expect min a string", lesson(step={"expect": [{"time": {"min": "a"}}]}),
     ["steps[0].expect[0]"]),
    ("expect tolerance negative", lesson(step={"expect": [{"time": 1, "tolerance": -1}]}),
     ["steps[0].expect[0]"]),
    ("expect velocity three", lesson(step={"expect": [{"block": "a", "velocity": [1, 2, 3]}]}),
     ["steps[0].expect[0]"]),
    ("expect fails", lesson(step={"expect": [{"block": "a", "vx": 99}]}),
     ["steps[0].expect[0]"]),
    ("pause never comes", lesson(step={"pause_at": {"first_collision_of": "b"},
                                       "scene": dict(SCENE, blocks=[
                                           dict(SCENE["blocks"][0], velocity=[0, 0]),
                                           SCENE["blocks"][1]])}),
     ["steps[0].pause_at"]),
    ("pause beyond the step budget",
     lesson(step={"overrides": {"frame_rate": 10000}, "pause_at": {"time": 600},
                  "scene": dict(SCENE, blocks=[
                      {"position": [0.5 + i, 6], "size": 0.5} for i in range(18)])}),
     ["steps[0].pause_at.time"]),
    ("second step bad", {"name": "L", "steps": [lesson()["steps"][0],
                                                lesson(step={"title": 5})["steps"][0]]},
     ["steps[1].title"]),
]

SYNTAX = re.compile(r"lesson\.json:\d+:\d+")
# (case, raw bytes of lesson.json, places)
RAW_CASES = [
    ("empty file", b"", ["lesson.json"]),
    ("whitespace only", b"  \n\t\n", ["lesson.json"]),
    ("truncated", json.dumps(lesson()).encode()[:-5], [SYNTAX]),
    ("trailing garbage", json.dumps(lesson()).encode() + b" {}", [SYNTAX]),
    ("duplicate key", b'{"name": "L", "name": "M", "steps": []}', [SYNTAX]),
    ("top-level array", b"[]", ["lesson.json"]),
    ("NaN bare", json.dumps(lesson(step={"pause_at": {"time": 1}})).encode().replace(
        b'"time": 1', b'"time": NaN'), [SYNTAX]),
    ("nan lowercase", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": nan'),
     [SYNTAX]),
    ("-nan", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": -nan'), [SYNTAX]),
    ("Infinity", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": Infinity'),
     [SYNTAX]),
    ("NaN as a string", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": "NaN"'),
     ["steps[0].pause_at.time"]),
    ("1e400", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": 1e400'),
     ["lesson.json"]),
    ("-1e400 in a scene",
     json.dumps(lesson()).encode().replace(b'"position": [4, 6]', b'"position": [-1e400, 6]'),
     ["lesson.json"]),
    ("400-digit integer", json.dumps(lesson()).encode().replace(b'"time": 1',
                                                                  b'"time": ' + b"9" * 400),
     ["lesson.json"]),
    ("hex number", json.dumps(lesson()).encode().replace(b'"time": 1', b'"time": 0x10'),
     [SYNTAX]),
    ("deep nesting 100000", b'{"name": "L", "steps": ' + b"[" * 100000 + b"]" * 100000 + b"}",
     ["lesson.json"]),
    ("deep nesting in a scene",
     json.dumps(lesson()).encode().replace(b'"gravity": [0, 0]',
                                           b'"gravity": ' + b"[" * 5000 + b"]" * 5000),
     ["lesson.json"]),
    ("UTF-8 BOM and a bad key", b"\xef\xbb\xbf" + json.dumps(lesson(top={"x": 1})).encode(),
     ["lesson.json"]),
    ("UTF-16 BOM", b"\xff\xfe" + json.dumps(lesson()).encode("utf-16-le"), ["lesson.json"]),
    ("NUL byte in the file", json.dumps(lesson()).encode().replace(b'"t"', b'"t\x00"'),
     ["lesson.json"]),
    ("NUL escaped in a name", json.dumps(lesson(step={"select": "a\u0000b"})).encode(),
     ["steps[0].select"]),
    ("invalid UTF-8 in a title", json.dumps(lesson()).encode().replace(b'"t"', b'"\xff\xfe"'),
     ["lesson.json"]),
    ("lone surrogate escape", json.dumps(lesson()).encode().replace(b'"t"', b'"\\ud800"'),
     ["lesson.json"]),
    ("huge steps array of numbers", b'{"name": "L", "steps": [' + b"1," * 3000000 + b"1]}",
     ["steps"]),
    ("200,001 blocks inline", json.dumps(lesson(step={"scene": dict(SCENE, blocks=[
        {"position": [0.5 + (i % 400) * 0.05, 0.5 + (i // 400) * 0.02], "size": 0.01}
        for i in range(200001)])})).encode(), ["steps[0].scene.blocks"]),
    ("65 MiB of spaces", b" " * (65 << 20) + json.dumps(lesson()).encode(), ["lesson.json"]),
]

# Names echoed back: escaped and cut, on stderr and on stdout (sandbox-cli lesson prints titles).
ECHO_CASES = [
    ("escape bytes in the title", lesson(step={"title": ESC_NAME}), ["steps[0].title"]),
    ("escape bytes in select", lesson(step={"select": ESC_NAME}), ["steps[0].select", "\\x1b"]),
    ("10 MB name in select", lesson(step={"select": "A" * 10000000}),
     ["steps[0].select", "10000000 bytes"]),
    ("escape bytes in an unknown key", lesson(step={ESC_NAME: 1}), ["steps[0]", "\\x1b"]),
    ("escape bytes in an overlay", lesson(step={"overlays": [ESC_NAME]}),
     ["steps[0].overlays[0]", "\\x1b"]),
    ("escape bytes in a quoted name in an answer", asking(answer="{'" + ESC_NAME + "'.vx}"),
     ["steps[0].answer", "control character"]),
    ("escape bytes in a value name", asking(values={ESC_NAME: "1"}), ["steps[0].values", "\\x1b"]),
    ("escape bytes in a block name, expect fails",
     lesson(step={"expect": [{"block": ESC_NAME, "vx": 99}],
                  "scene": dict(SCENE, blocks=[dict(SCENE["blocks"][0], name=ESC_NAME),
                                               SCENE["blocks"][1]])}),
     ["steps[0].expect[0]", "\\x1b"]),
    ("C1 control in a first_collision_of", lesson(step={"pause_at": {
        "first_collision_of": "\u009b31m"}}), ["steps[0].pause_at.first_collision_of"]),
]

# Good lessons whose text the programs print: the text must come out escaped, exit 0.
GOOD_ECHO_CASES = [
    ("escape bytes in a block name printed",
     lesson(step={"scene": dict(SCENE, blocks=[dict(SCENE["blocks"][0], name=ESC_NAME),
                                               SCENE["blocks"][1]])})),
    ("largest frame rate at the largest time, one block",
     lesson(step={"overrides": {"frame_rate": 10000}, "pause_at": {"time": 600},
                  "scene": dict(SCENE, blocks=[SCENE["blocks"][0]])})),
]


def scene_file(folder, name="s.json", scene=None):
    write(os.path.join(folder, name), json.dumps(scene or SCENE))


def fifo(path):
    os.mkfifo(path)


# (case, setup(folder) -> value of steps[0].scene, places). The lesson is folder/lesson.json.
def path_cases(outside):
    def link(target, name="s.json"):
        def setup(folder):
            os.symlink(target, os.path.join(folder, name))
            return name
        return setup

    def named(setup_fn, value):
        def setup(folder):
            setup_fn(folder)
            return value
        return setup

    def loop(folder):
        os.symlink("b.json", os.path.join(folder, "a.json"))
        os.symlink("a.json", os.path.join(folder, "b.json"))
        return "a.json"

    return [
        ("absolute /dev/zero", lambda f: "/dev/zero", ["steps[0].scene"]),
        ("absolute path to a good scene",
         named(lambda f: scene_file(f), None), ["steps[0].scene"]),  # value filled in below
        ("link to /dev/zero", link("/dev/zero"), ["steps[0].scene"]),
        ("link to /dev/stdin", link("/dev/stdin"), ["steps[0].scene"]),
        ("link to /dev/urandom", link("/dev/urandom"), ["steps[0].scene"]),
        ("a directory", named(lambda f: os.mkdir(os.path.join(f, "sub")), "sub"),
         ["steps[0].scene"]),
        ("a directory named .json", named(lambda f: os.mkdir(os.path.join(f, "d.json")),
                                          "d.json"), ["steps[0].scene"]),
        ("a FIFO", named(lambda f: fifo(os.path.join(f, "p.json")), "p.json"),
         ["steps[0].scene"]),
        ("the lesson itself", lambda f: "lesson.json", ["steps[0].scene"]),
        ("the lesson itself by ./", lambda f: "./lesson.json", ["steps[0].scene"]),
        ("the lesson itself by sub/..",
         named(lambda f: os.mkdir(os.path.join(f, "sub")), "sub/../lesson.json"),
         ["steps[0].scene"]),
        ("the lesson itself by a link", link("lesson.json", "me.json"), ["steps[0].scene"]),
        ("the lesson itself by a hard link",
         named(lambda f: (write(os.path.join(f, "lesson.json"), "{}"),
                         os.link(os.path.join(f, "lesson.json"), os.path.join(f, "h.json"))),
               "h.json"), ["steps[0].scene"]),
        ("outside by ..", lambda f: os.path.relpath(outside, f), ["steps[0].scene"]),
        ("outside by a link", link(outside), ["steps[0].scene"]),
        ("outside by a linked folder",
         named(lambda f: os.symlink(os.path.dirname(outside), os.path.join(f, "up")),
               "up/" + os.path.basename(outside)), ["steps[0].scene"]),
        ("a link loop", loop, ["steps[0].scene", "is a loop of symbolic links"]),
        ("a link to itself", link("s.json"), ["steps[0].scene", "is a loop of symbolic links"]),
        ("gone", lambda f: "gone.json", ["steps[0].scene"]),
        ("a control-byte path", lambda f: "x\x1b[2Jy.json", ["steps[0].scene", "\\x1b"]),
        ("a 100 kB path", lambda f: "a/" * 50000 + "s.json", ["steps[0].scene"]),
        ("an empty path", lambda f: "", ["steps[0].scene"]),
        ("a scene file with a bad mass",
         named(lambda f: scene_file(f, "bad.json", dict(SCENE, blocks=[
             dict(SCENE["blocks"][0], mass="heavy")])), "bad.json"),
         ["steps[0].scene", "bad.json", "blocks[0].mass"]),
        ("a scene file that is a lesson",
         named(lambda f: write(os.path.join(f, "l2.json"), json.dumps(lesson())), "l2.json"),
         ["steps[0].scene", "l2.json"]),
        ("a scene file of 65 MiB",
         named(lambda f: write(os.path.join(f, "big.json"), b" " * (65 << 20) + b"{}"),
               "big.json"), ["steps[0].scene", "big.json"]),
        ("a scene file that is a link to a FIFO inside",
         named(lambda f: (fifo(os.path.join(f, "p")), os.symlink("p", os.path.join(f, "q.json"))),
               "q.json"), ["steps[0].scene"]),
    ]


# Cases that load and fail only when run to the pause point: the CLI's checks, not offscreen's.
RUNTIME_CASES = {"expect fails", "pause never comes", "escape bytes in a block name, expect fails",
                 "marked choice contradicted", "a second choice proved too"}


def programs(suite, path, cwd, case=""):
    """The three ways a lesson is read: validate, lesson, offscreen --lesson."""
    shot = os.path.join(cwd, "shot.png")
    ways = [
        ("validate", [suite.cli, "validate", path], False),
        ("lesson", [suite.cli, "lesson", path], True),
        ("offscreen", [suite.offscreen, "--lesson", path, "--screenshot", shot], False),
    ]
    return ways[:2] if case in RUNTIME_CASES else ways


def expect_refused(suite, case, folder, path, places, code=1, timeout=180):
    before = read(path) if os.path.isfile(path) and not os.path.islink(path) else None
    for program, args, echo in programs(suite, path, folder, case):
        result = run_program(args, folder, timeout)
        problems = suite.refused(result, places, code=code, echo_stdout=echo)
        if before is not None and read(path) != before:
            problems.append("the lesson file changed")
        suite.check("%s [%s]" % (case, program), problems, result)


def run_cases(suite):
    for case, doc, places in KEY_CASES + ECHO_CASES:
        folder = suite.folder(case)
        path = os.path.join(folder, "lesson.json")
        write(path, json.dumps(doc))
        expect_refused(suite, case, folder, path, ["lesson.json"] + places)

    for case, raw, places in RAW_CASES:
        folder = suite.folder(case)
        path = os.path.join(folder, "lesson.json")
        write(path, raw)
        expect_refused(suite, case, folder, path, places)

    for case, doc in GOOD_ECHO_CASES:
        folder = suite.folder(case)
        path = os.path.join(folder, "lesson.json")
        write(path, json.dumps(doc))
        for program, args, echo in programs(suite, path, folder):
            result = run_program(args, folder, 600)
            suite.check("%s [%s]" % (case, program), suite.accepted(result, echo), result)

    outside = os.path.join(suite.root, "outside.json")
    scene_file(suite.root, "outside.json")
    for case, setup, places in path_cases(outside):
        folder = suite.folder("path " + case)
        value = setup(folder)
        if value is None:
            value = os.path.join(folder, "s.json")
        path = os.path.join(folder, "lesson.json")
        write(path, json.dumps(lesson(step={"scene": value})))
        expect_refused(suite, "path " + case, folder, path, ["lesson.json"] + places)

    # The lesson file itself is not a regular file, or not there.
    folder = suite.folder("lesson file kinds")
    fifo(os.path.join(folder, "fifo.json"))
    os.mkdir(os.path.join(folder, "dir.json"))
    os.symlink("loop.json", os.path.join(folder, "loop.json"))
    for name in ["/dev/zero", "/dev/stdin", "/dev/urandom", "fifo.json", "dir.json",
                 "loop.json", "gone.json", "bad\x1b[2Jname.json"]:
        case = "lesson file " + name.replace("\x1b", "ESC")
        for program, args, echo in programs(suite, name, folder):
            result = run_program(args, folder, 120)
            places = ["\\x1b"] if "\x1b" in name else [os.path.basename(name)]
            if name == "loop.json":
                places.append("a loop of symbolic links")
            suite.check("%s [%s]" % (case, program), suite.refused(result, places, echo_stdout=echo), result)

    # --step takes only the lesson's step numbers.
    folder = suite.folder("step numbers")
    path = os.path.join(folder, "lesson.json")
    write(path, json.dumps(lesson()))
    for step in ["0", "2", "-1", "1.5", "abc", "99999999999999999999", "1e0", ""]:
        args = [suite.offscreen, "--lesson", path, "--step", step, "--screenshot",
                os.path.join(folder, "s.png")]
        result = run_program(args, folder, 120)
        places = ["lesson.json", "no step 2"] if step == "2" else ["--step"]
        suite.check("--step %r [offscreen]" % step, suite.refused(result, places), result)
    result = run_program([suite.offscreen, "--lesson", path, "--step", "1", "--screenshot",
                             os.path.join(folder, "s.png")], folder, 60)
    suite.check("--step 1 [offscreen]", suite.accepted(result), result)

    # A shipped scene by name is fine (the control case for the path rules).
    folder = suite.folder("shipped scene")
    path = os.path.join(folder, "lesson.json")
    write(path, json.dumps(lesson(step={"scene": "bullet_wall", "pause_at": {"time": 0.1}})))
    for program, args, echo in programs(suite, path, folder):
        result = run_program(args, folder, 300)
        suite.check("shipped scene by name [%s]" % program, suite.accepted(result, echo), result)


def run_program(args, cwd, timeout):
    return run(args, cwd, timeout=timeout, mem_mb=2048)
