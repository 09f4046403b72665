#!/usr/bin/env python3
"""A student's engine, written for the tests apart from the sandbox's (issue 29, "Check your own
engine"): Assignment 3's axis-aligned blocks as the course's C# code would have them, in single
precision, turn-based (each block moves until its first collision, the others held still), the
point of impact t = a/b, and the lecture's formula on the collision's axis. One mistake can be
built in:
  --mistake move-back       move the whole frame, then back out along the collision axis only
  --mistake put-back        put back where the frame started, not at the point of impact
  --mistake not-corrected   move the whole frame and leave the blocks overlapping
  --mistake wrong-axis      the formula applied to the other coordinate of the velocities
  --mistake both-axes       the formula applied to both coordinates
  --mistake reflect         each block reverses its own velocity, v' = -C v (without Newton)
  --mistake formula-sign    v' = u + C (v - u)
  --mistake masses-swapped  u = (m2 v1 + m1 v2) / (m1 + m2)
  --mistake bounciness      C = 1 whatever the scene says
  --mistake explicit-euler  move with the velocity from before gravity was added
It prints what the student would print from Step(): one row per frame, in SI units or, with
--units gxp, in pixels with y down and velocities in pixels per frame; --european writes
semicolons and decimal commas as a spreadsheet in Europe does.

  student_engine.py SCENE.json FRAMES OUT.csv [--mistake M] [--units gxp --px-per-m N
                    --px-origin X,Y] [--european]
"""
import argparse
import json
import struct


def f32(x):
    """x rounded to single precision, as every float in the student's C# engine."""
    return struct.unpack("f", struct.pack("f", x))[0]


class Body:
    def __init__(self, d):
        self.name = d.get("name", "")
        size = d.get("size", 1)
        self.w, self.h = (size, size) if not isinstance(size, list) else size
        self.w, self.h = f32(self.w), f32(self.h)
        self.x, self.y = (f32(c) for c in d["position"])
        self.vx, self.vy = (f32(c) for c in d.get("velocity", [0, 0]))
        mass = d.get("mass", 1)
        self.static = mass == "static"
        self.m = None if self.static else f32(mass)

    def half(self, axis):
        return f32(0.5 * (self.w if axis == 0 else self.h))

    def pos(self, axis):
        return self.x if axis == 0 else self.y

    def vel(self, axis):
        return self.vx if axis == 0 else self.vy

    def set_vel(self, axis, v):
        if axis == 0:
            self.vx = f32(v)
        else:
            self.vy = f32(v)


INF = float("inf")
MISTAKES = ["none", "move-back", "put-back", "not-corrected", "wrong-axis", "both-axes", "reflect",
            "formula-sign", "masses-swapped", "bounciness", "explicit-euler"]


def entry_exit(lo_a, hi_a, lo_b, hi_b, v, frame):
    """Times (as fractions of the frame) at which A's faces enter and leave B's span along one
    axis, A moving at v per frame and B held still."""
    if v > 0:
        return f32((lo_b - hi_a) / (v * frame)), f32((hi_b - lo_a) / (v * frame))
    if v < 0:
        return f32((hi_b - lo_a) / (v * frame)), f32((lo_b - hi_a) / (v * frame))
    if hi_a <= lo_b or lo_a >= hi_b:
        return INF, -INF
    return -INF, INF


def impact_with(a, b, frame):
    """(t, axis) of A's first touch of B within the frame, B held still; None if it misses."""
    spans = []
    for axis in (0, 1):
        ha, hb = a.half(axis), b.half(axis)
        spans.append(entry_exit(f32(a.pos(axis) - ha), f32(a.pos(axis) + ha),
                                f32(b.pos(axis) - hb), f32(b.pos(axis) + hb), a.vel(axis), frame))
    enter = max(spans[0][0], spans[1][0])
    leave = min(spans[0][1], spans[1][1])
    if enter > leave or enter > 1 or enter < 0 or leave <= 0:
        return None
    axis = 0 if spans[0][0] >= spans[1][0] else 1
    return enter, axis


def impact_with_walls(a, bounds, frame):
    best = None
    for axis in (0, 1):
        v = a.vel(axis)
        if v == 0:
            continue
        h = a.half(axis)
        gap = f32(bounds[2 + axis] - (a.pos(axis) + h)) if v > 0 else f32(bounds[axis] - (a.pos(axis) - h))
        t = f32(gap / (v * frame))
        if 0 <= t <= 1 and (best is None or t < best[0]):
            best = (t, axis)
    return best


def step(bodies, bounds, gravity, c, frame, mistake):
    if mistake == "bounciness":
        c = 1.0
    if mistake != "explicit-euler":
        accelerate(bodies, gravity, frame)
    for a in bodies:
        if a.static:
            continue
        first, other = impact_with_walls(a, bounds, frame), None
        for b in bodies:
            if b is a:
                continue
            hit = impact_with(a, b, frame)
            if hit and (first is None or hit[0] < first[0]):
                first, other = hit, b
        if first is None:
            a.x = f32(a.x + f32(a.vx * frame))
            a.y = f32(a.y + f32(a.vy * frame))
            continue
        t, axis = first
        poi = (f32(a.x + f32(t * f32(a.vx * frame))), f32(a.y + f32(t * f32(a.vy * frame))))
        whole = (f32(a.x + f32(a.vx * frame)), f32(a.y + f32(a.vy * frame)))
        if mistake == "move-back":  # the whole frame, then back along the collision axis only
            a.x, a.y = (poi[0], whole[1]) if axis == 0 else (whole[0], poi[1])
        elif mistake == "not-corrected":
            a.x, a.y = whole
        elif mistake != "put-back":  # put-back: left where the frame started
            a.x, a.y = poi
        # The formula on one coordinate: u = (m1 v1 + m2 v2)/(m1 + m2), v' = u - C (v - u), only
        # when the relative velocity closes.
        side = 1.0 if (other is None and a.vel(axis) > 0) or (
            other is not None and other.pos(axis) > a.pos(axis)) else -1.0
        if f32((a.vel(axis) - (0.0 if other is None else other.vel(axis))) * side) <= 0:
            continue  # separating: not a collision
        axes = {"wrong-axis": [1 - axis], "both-axes": [0, 1]}.get(mistake, [axis])
        for resolve_axis in axes:
            resolve(a, other, resolve_axis, c, mistake)
    if mistake == "explicit-euler":
        accelerate(bodies, gravity, frame)


def accelerate(bodies, gravity, frame):
    for a in bodies:
        if not a.static:
            a.vx = f32(a.vx + f32(gravity[0] * frame))
            a.vy = f32(a.vy + f32(gravity[1] * frame))


def resolve(a, other, axis, c, mistake):
    """The lecture's formula along one axis, or the mistake built in."""
    v1 = a.vel(axis)
    v2 = 0.0 if other is None else other.vel(axis)
    if mistake == "reflect":
        a.set_vel(axis, f32(-c * v1))
        if other is not None and not other.static:
            other.set_vel(axis, f32(-c * v2))
        return
    sign = 1.0 if mistake == "formula-sign" else -1.0
    if other is None or other.static:
        u = v2
        a.set_vel(axis, f32(u + sign * f32(c * f32(v1 - u))))
        return
    m1, m2 = (other.m, a.m) if mistake == "masses-swapped" else (a.m, other.m)
    u = f32(f32(f32(m1 * v1) + f32(m2 * v2)) / f32(m1 + m2))
    a.set_vel(axis, f32(u + sign * f32(c * f32(v1 - u))))
    other.set_vel(axis, f32(u + sign * f32(c * f32(v2 - u))))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("frames", type=int)
    p.add_argument("out")
    p.add_argument("--mistake", default="none", choices=MISTAKES)
    p.add_argument("--units", default="si", choices=["si", "gxp"])
    p.add_argument("--px-per-m", type=float, default=1.0)
    p.add_argument("--px-origin", default="0,0")
    p.add_argument("--european", action="store_true")
    args = p.parse_args()
    scene = json.load(open(args.scene))
    world = scene["world"]
    bounds = [f32(c) for c in world["bounds"]]
    gravity = [f32(c) for c in world.get("gravity", [0, -9.81])]
    c = f32(world.get("bounciness", 1))
    frame = f32(world.get("dt", 1 / 60))
    bodies = [Body(d) for d in scene["blocks"]]
    moving = [b for b in bodies if not b.static]
    ox, oy = (float(v) for v in args.px_origin.split(","))
    sep = ";" if args.european else ","

    def number(x):
        text = repr(f32(x))
        return text.replace(".", ",") if args.european else text

    with open(args.out, "w") as out:
        header = ["t"]
        for b in moving:
            header += [b.name + "_x", b.name + "_y", b.name + "_vx", b.name + "_vy"]
        out.write(sep.join(header) + "\n")
        t = f32(0)
        for _ in range(args.frames):
            step(bodies, bounds, gravity, c, frame, args.mistake)
            t = f32(t + frame)
            row = [t]
            for b in moving:
                if args.units == "gxp":
                    k = args.px_per_m
                    row += [ox + (b.x - bounds[0]) * k, oy + (bounds[3] - b.y) * k,
                            b.vx * k * frame, -b.vy * k * frame]
                else:
                    row += [b.x, b.y, b.vx, b.vy]
            out.write(sep.join(number(v) for v in row) + "\n")


main()
