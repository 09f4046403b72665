#!/usr/bin/env python3
"""Counts the frames in which kinetic plus potential energy rises, for the random piles of issue 41.

A pile: N blocks of 0.9 m, 1 kg, in a 16 m x 12 m box, in rows of 12 at x = 1 + 1.2·i,
y = 1 + 1.3·j, each with a velocity (vx, vy) drawn uniformly in ±3 m/s from Python's
random.Random(seed) (vx first), gravity -9.81 m/s², dt 1/60, one substep. The script writes the
scene, runs `sandbox-cli run --trace` on it and prints, per case, the frames whose energy rose
(more than `--tolerance` of the start's magnitude: 1e-9 by default), the largest rise in J and
its frame, and the energy at the start and at the end.

    tools/energy_piles.py [--cli build/app/cli/sandbox-cli] [--frames 600]
        [CASE ...]   where CASE is METHOD:INTEGRATOR:C:MU:SEED:N, e.g. perfect:exact:0.6:0:1:60

Without cases it prints the table of issue 41 (docs/physics.md, "Energy in piles").
"""
import argparse
import csv
import json
import os
import random
import subprocess
import sys
import tempfile

ISSUE_CASES = [
    # issue 41's measurements
    "perfect:exact:0.6:0:1:60",
    "perfect:exact:0.6:0.4:1:60",
    "perfect:exact:0.9:0:7:60",
    "perfect:exact:1:0:1:60",
    "perfect:semi-implicit-euler:0.6:0:1:60",
    "perfect:semi-implicit-euler:0.6:0.4:1:60",
    "perfect:semi-implicit-euler:0.6:0:3:60",
    "perfect:semi-implicit-euler:0.6:0.4:3:60",
    "perfect:semi-implicit-euler:1:0:5:40",
    # friction 2 between blocks (an endless loop of merges at one instant, ended by the event cap)
    "perfect:semi-implicit-euler:0:2:2:40",
    # move-and-correct's corrections under the exact integrator
    "move-and-correct:exact:0.99:0:4:20",
    # turn-based near C = 1 (a known failure: docs/physics.md)
    "turn-based:semi-implicit-euler:0.99:0:1:96",
    "turn-based:semi-implicit-euler:0.95:0:5:60",
]


def pile_scene(seed, count, bounciness, friction, method, integrator):
    rng = random.Random(seed)
    blocks = []
    for k in range(count):
        i, j = k % 12, k // 12
        vx = rng.uniform(-3.0, 3.0)
        vy = rng.uniform(-3.0, 3.0)
        blocks.append({"name": "b%d" % k, "position": [1 + 1.2 * i, 1 + 1.3 * j],
                       "size": [0.9, 0.9], "velocity": [vx, vy], "mass": 1})
    return {"name": "pile %d seed %d" % (count, seed),
            "world": {"bounds": [0, 0, 16, 12], "gravity": [0, -9.81],
                      "bounciness": bounciness, "friction": friction, "method": method,
                      "integrator": integrator, "dt": 1 / 60, "substeps": 1},
            "blocks": blocks}


def energies(cli, scene, frames, workdir):
    path = os.path.join(workdir, "pile.json")
    trace = os.path.join(workdir, "trace.csv")
    with open(path, "w") as f:
        json.dump(scene, f)
    subprocess.run([cli, "run", path, "--steps", str(frames), "--trace", trace, "--json"],
                   check=True, stdout=subprocess.DEVNULL)
    # The start: the scene's energy before the first frame.
    e0 = sum(0.5 * b["mass"] * (b["velocity"][0] ** 2 + b["velocity"][1] ** 2) +
             9.81 * b["mass"] * b["position"][1] for b in scene["blocks"])
    with open(trace) as f:
        rows = list(csv.DictReader(f))
    return e0, [float(r["kinetic_energy"]) + float(r["potential_energy"]) for r in rows]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=os.path.join(here, "..", "build", "app", "cli",
                                                      "sandbox-cli"))
    parser.add_argument("--frames", type=int, default=600)
    parser.add_argument("--tolerance", type=float, default=1e-9)
    parser.add_argument("cases", nargs="*")
    args = parser.parse_args()
    cases = args.cases or ISSUE_CASES
    print("%-46s %6s %12s %6s %12s %12s" % ("case (method:integrator:C:mu:seed:N)", "rising",
                                            "max rise J", "frame", "start J", "end J"))
    with tempfile.TemporaryDirectory() as workdir:
        for case in cases:
            method, integrator, c, mu, seed, count = case.split(":")
            scene = pile_scene(int(seed), int(count), float(c), float(mu), method, integrator)
            e0, e = energies(args.cli, scene, args.frames, workdir)
            before = [e0] + e[:-1]
            rises = [(after - prev, f + 1) for f, (prev, after) in enumerate(zip(before, e))]
            rising = [r for r in rises if r[0] > args.tolerance * abs(e0)]
            top = max(rises)
            print("%-46s %6d %12.3g %6d %12.6f %12.6f" % (case, len(rising), max(0.0, top[0]),
                                                          top[1] if top[0] > 0 else 0, e0, e[-1]))


if __name__ == "__main__":
    sys.exit(main())
