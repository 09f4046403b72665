#!/usr/bin/env python3
"""sandbox-cli compare on traces from an engine written apart from the project
(student_engine.py: Python, single precision, turn-based, gxp units, European CSV), one mistake
built in at a time: each is diagnosed with that mistake (issue 29, "Done when").

  student_engine_test.py SANDBOX_CLI SCENES_DIR WORK_DIR
"""
import json
import os
import subprocess
import sys

cli, scenes, work = sys.argv[1:4]
here = os.path.dirname(os.path.abspath(__file__))
failures = []
GXP = ["--units", "gxp", "--px-per-m", "50", "--px-origin", "40,30"]


def scene_file(scene):
    """A shipped scene, or one this test wrote into WORK_DIR."""
    written = os.path.join(work, scene + ".json")
    return written if os.path.exists(written) else os.path.join(scenes, scene + ".json")


def student(scene, frames, mistake, gxp=True):
    out = os.path.join(work, "student_%s_%s_%d.csv" % (scene, mistake, frames))
    args = [sys.executable, os.path.join(here, "student_engine.py"),
            scene_file(scene), str(frames), out, "--mistake", mistake]
    if gxp:
        args += GXP + ["--european"]
    subprocess.run(args, check=True)
    return out


def compare(scene, trace, *options, gxp=True):
    args = [cli, "compare", scene_file(scene), trace, "--json"]
    args += list(options) + (GXP if gxp else [])
    run = subprocess.run(args, capture_output=True, text=True, timeout=120)
    try:
        return run.returncode, json.loads(run.stdout)
    except json.JSONDecodeError:
        return run.returncode, {"stderr": run.stderr}


def check(ok, what, report):
    if not ok:
        failures.append(what)
        print("FAILED:", what)
        print(json.dumps(report, indent=1)[:3000])


def finding_ids(report):
    return [f["id"] for f in report.get("findings", [])]


def variant(report):
    v = report.get("diagnosis", {}).get("variant")
    return v["name"] if v else None


# The student's correct engine is the reference's turn-based method, to float rounding: the same.
for scene, frames in (("point_of_impact", 200), ("lecture_example_1", 300),
                      ("single_bounce", 200)):
    code, r = compare(scene, student(scene, frames, "none"), "--method", "turn-based")
    check(code == 0 and r.get("result") == "same", scene + ": the correct engine is the same", r)
    check(0 < r.get("max_position_error", 1) < 1e-4,
          scene + ": single-precision rounding stays below 1e-4 m", r)

# Against the scene's own method (perfect): the engine is told to be turn-based.
code, r = compare("point_of_impact", student("point_of_impact", 200, "none"))
check(code == 3 and variant(r) == "method turn-based",
      "point_of_impact: the correct engine is the turn-based method", r)
check("stops-at-impact" in finding_ids(r), "point_of_impact: it stops at the point of impact", r)

# Move-back: the sandbox's switch explains it, and the parting collision shows it.
trace = student("point_of_impact", 200, "move-back")
code, r = compare("point_of_impact", trace, "--method", "turn-based")
check(code == 3 and variant(r) == "mistake move-back", "move-back diagnosed as move-back", r)
check(finding_ids(r) == ["move-back"], "move-back seen at the parting collision", r)
check(r.get("collision", {}).get("axis") == "y" and r["collision"].get("other") == "floor step",
      "move-back: the collision is the mover on the floor step along y", r)
code, r = compare("point_of_impact", trace)
check(code == 3 and variant(r) == "method turn-based + mistake move-back",
      "move-back against the perfect reference: turn-based with move-back", r)

# The formula on the wrong axis: no switch models it; the parting collision names it.
for scene in ("point_of_impact", "mistake_move_back"):
    code, r = compare(scene, student(scene, 200, "wrong-axis"), "--method", "turn-based")
    check(code == 3 and variant(r) is None, scene + ": no variant explains the wrong axis", r)
    check(finding_ids(r) == ["wrong-axis"], scene + ": the formula on the wrong axis", r)
    text = " ".join(r.get("diagnosis", {}).get("text", []))
    check("wrong axis" in text and "Tips" in text, scene + ": said with the Tips slide", r)

# A corner: the student's engine resolves one axis, the sandbox both (a convention).
code, r = compare("point_of_impact", student("point_of_impact", 300, "none"),
                  "--method", "turn-based")
check(code == 3 and finding_ids(r) == ["corner"], "point_of_impact: the corner at frame 263", r)

# Every other mistake built in, one at a time, named at the collision where the two part; where a
# switch of the sandbox models it, that variant reproduces the whole trace too. The lecture's
# example with C = 0.8 (written here), so the formula's sign, the masses in u and the bounciness
# each give another velocity (with C = 1, u + C·(v - u) is v: the sign would look unresolved).
example = json.load(open(os.path.join(scenes, "lecture_example_1.json")))
example["world"]["bounciness"] = 0.8
with open(os.path.join(work, "lecture_example_1_c08.json"), "w") as f:
    json.dump(example, f)
PLANTED = (  # (scene, frames, mistake, the finding, the variant that reproduces it or None)
    ("lecture_example_1_c08", 300, "reflect", "without-newton", "resolve reflect"),
    ("lecture_example_1_c08", 300, "formula-sign", "formula-sign", None),
    ("lecture_example_1_c08", 300, "masses-swapped", "masses-swapped", None),
    ("lecture_example_1_c08", 300, "bounciness", "bounciness", None),
    ("point_of_impact", 200, "both-axes", "both-axes", None),
    ("point_of_impact", 200, "put-back", "put-back", None),
    ("point_of_impact", 200, "not-corrected", "not-corrected", None),
    ("single_bounce", 200, "explicit-euler", "explicit-euler", "integrator explicit-euler"),
)
code, r = compare("lecture_example_1_c08", student("lecture_example_1_c08", 300, "none"),
                  "--method", "turn-based")
check(code == 0, "lecture_example_1 with C = 0.8: the correct engine is the same", r)
for scene, frames, mistake, finding, expected in PLANTED:
    code, r = compare(scene, student(scene, frames, mistake), "--method", "turn-based")
    what = "%s, %s built in" % (scene, mistake)
    check(code == 3, what + ": different", r)
    check(finding_ids(r) == [finding], what + ": named " + finding, r)
    check(variant(r) == expected, what + ": the variant is %s" % expected, r)
    text = " ".join(r.get("diagnosis", {}).get("text", []))
    check("(slide '" in text, what + ": the diagnosis names its slide", r)

# In SI units, plain CSV, the same results.
code, r = compare("point_of_impact", student("point_of_impact", 200, "move-back", gxp=False),
                  "--method", "turn-based", gxp=False)
check(code == 3 and variant(r) == "mistake move-back", "SI units: move-back", r)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
