"""Energy at the extremes (issue 28): valid scenes at the edge of the valid range, built here from
the issue's description (not the project's files). docs/cli.md, "No silent blow-up": when
kinetic plus potential energy ends more than 10 times its start in a scene where nothing adds
any, `sandbox-cli run` warns on stderr with both energies, the factor and the method; the run
ends, exit 0, every number finite. The warning is checked both ways: given when the energy grew
more than tenfold with nothing adding any, never given otherwise."""
import json
import math
import os
import re

from hostile_outside import run

WARNING = re.compile(r"energy grew from (\S+) J to (\S+) J \(x(\S+)\)")


def gas(columns, rows, size, speed, world, heavy=None):
    """Blocks on a grid inside world["bounds"], velocities from a fixed sequence (no randomness)."""
    xmin, ymin, xmax, ymax = world["bounds"]
    pitch_x, pitch_y = (xmax - xmin) / columns, (ymax - ymin) / rows
    blocks = []
    for i in range(columns * rows):
        c, r = i % columns, i // columns
        angle = 2.399963 * i  # the golden angle: directions spread without a generator
        blocks.append({"name": "g%d" % i,
                       "position": [xmin + (c + 0.5) * pitch_x, ymin + (r + 0.5) * pitch_y],
                       "size": size,
                       "velocity": [speed * math.cos(angle), speed * math.sin(angle)]})
    if heavy:
        blocks[len(blocks) // 2]["mass"] = heavy
    return {"name": "extreme", "world": world, "blocks": blocks}


# Issue 28's first case: turn-based, dt = 1 s, a 180-block gas under gravity, C = 1.
TURN_BASED_GAS = gas(18, 10, 0.25, 3.0, {"bounds": [0, 0, 20, 12], "gravity": [0, -9.81],
                                        "bounciness": 1, "method": "turn-based", "dt": 1})
# The second: perfect, a world of +-1e9 m, a 1e15 kg block, speeds and gravity of 1e9, C = 1:
# the heavy block falls on 60 light ones bouncing on the floor, which meet it ever more often.
PERFECT_EDGE = {
    "name": "crusher",
    "world": {"bounds": [-1e9, -1e9, 1e9, 1e9], "gravity": [0, -1e9], "bounciness": 1,
              "method": "perfect", "dt": 1 / 60},
    "blocks": [{"name": "g%d" % i, "position": [-4.5e8 + i * 9e8 / 59, -9.8e8], "size": 1e7,
                "velocity": [0, 1e9 if i % 2 else -1e9]} for i in range(60)] +
              [{"name": "heavy", "position": [0, -7e8], "size": [1e9, 2e8],
                "velocity": [0, -1e9], "mass": 1e15}]}
# Energy that falls: C = 0.5 under gravity.
FALLING = gas(4, 2, 0.5, 0.0, {"bounds": [0, -100, 20, -1], "gravity": [0, -9.81],
                                      "bounciness": 0.5})
# Energy that a force adds: not the method's doing, so no warning.
THRUSTER = {"name": "thruster", "world": {"bounds": [-1e6, -1e6, 1e6, 1e6], "gravity": [0, 0]},
            "blocks": [{"name": "ship", "position": [0, 0], "size": 1, "velocity": [1, 0],
                        "force": [100, 0]}]}
AT_REST = {"name": "rest", "world": {"gravity": [0, 0]},
           "blocks": [{"name": "a", "position": [5, 5], "size": 1}]}


def energy(summary):
    return summary["kinetic_energy"] + summary["potential_energy"]


def finite_json(result):
    """The --json summary, or a problem: not one object, or a number that is not finite."""
    try:
        summary = json.loads(result.out.decode("ascii"))
    except (ValueError, UnicodeDecodeError) as e:
        return None, "stdout is not one ASCII JSON object (%s)" % e

    def numbers(x):
        if isinstance(x, dict):
            for v in x.values():
                yield from numbers(v)
        elif isinstance(x, list):
            for v in x:
                yield from numbers(v)
        elif isinstance(x, (int, float)) and not isinstance(x, bool):
            yield x
    if not all(math.isfinite(v) for v in numbers(summary)):
        return None, "a number in the summary is not finite"
    return summary, None


def run_cases(suite):
    cases = [
        ("turn-based gas dt 1 s, 600 s", TURN_BASED_GAS, ["--time", "600"], True),
        ("the same gas, perfect", TURN_BASED_GAS, ["--time", "600", "--method", "perfect"], True),
        ("the same gas, move-and-correct", TURN_BASED_GAS,
         ["--time", "600", "--method", "move-and-correct"], True),
        ("the same gas, exact integrator", TURN_BASED_GAS,
         ["--time", "600", "--integrator", "exact"], True),
        ("the same gas, explicit Euler, reflect", TURN_BASED_GAS,
         ["--time", "600", "--integrator", "explicit-euler", "--resolve", "reflect"], True),
        ("perfect at 1e9, 600 frames", PERFECT_EDGE, ["--steps", "600"], True),
        ("the 1e9 world, turn-based", PERFECT_EDGE, ["--steps", "600", "--method", "turn-based"],
         True),
        ("the 1e9 world, move-and-correct", PERFECT_EDGE,
         ["--steps", "600", "--method", "move-and-correct"], True),
        ("a falling gas with C = 0.5 loses energy", FALLING, ["--time", "30"], True),
        ("a thruster adds energy", THRUSTER, ["--time", "600"], False),
        ("zero energy at the start", AT_REST, ["--steps", "100"], True),
    ]
    folder = suite.folder("energy")
    for case, scene, args, nothing_adds in cases:
        path = os.path.join(folder, re.sub(r"\W+", "_", case) + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        start = run([suite.cli, "run", path, "--steps", "0", "--json"], folder, timeout=60)
        result = run([suite.cli, "run", path, "--json"] + args, folder, timeout=900,
                     mem_mb=2048)
        problems = suite.accepted(start) + suite.accepted(result)
        first, error = finite_json(start)
        last, error2 = finite_json(result)
        problems += [e for e in (error, error2) if e]
        stderr = result.err.decode("utf-8", "replace")
        warned = WARNING.search(stderr)
        if first and last:
            e0, e1 = energy(first), energy(last)
            grew = e0 > 0 and e1 > 10 * e0 or e0 <= 0 and e1 > 0 and e1 > e0 + 10 * abs(e0)
            if nothing_adds and grew and not warned:
                problems.append("energy grew from %g J to %g J with no warning" % (e0, e1))
            if warned and not (nothing_adds and grew):
                problems.append("warned, but the energy went from %g J to %g J%s" % (
                    e0, e1, "" if nothing_adds else " with a force adding it"))
            if warned and not problems:
                a, b, factor = (float(v.rstrip(",:;")) for v in warned.groups())
                for shown, true in ((a, e0), (b, e1)):
                    if not math.isclose(shown, true, rel_tol=1e-2):
                        problems.append("the warning says %g J, the summary %g J" % (shown,
                                                                                   true))
                if not math.isclose(factor, e1 / e0, rel_tol=2e-2):
                    problems.append("the warning's factor x%g is not %g" % (factor, e1 / e0))
                if last["method"] not in stderr:
                    problems.append("the warning does not name the method %s" % last["method"])
            print("     %s: %.4g J -> %.4g J (x%.3g), %s event-cap hits, t = %s s%s" % (
                case, e0, e1, e1 / e0 if e0 else float("nan"), last.get("event_cap_hits"),
                last.get("sim_time"), ", warned" if warned else ""))
        if "NaN" in stderr or "nan" in stderr.split():
            problems.append("NaN in the warning")
        suite.check(case, problems, result)
