#!/usr/bin/env python3
"""Writes a gas scene (format v1): square blocks on a grid, no gravity, C = 1, velocities from a
fixed pseudo-random sequence (the same file every run).

    tools/make_gas_scene.py COLUMNS ROWS [SIZE] [MAX_SPEED] > app/scenes/gas_500.json
app/scenes/gas_500.json is `tools/make_gas_scene.py 25 20`.
"""
import json
import math
import sys


def main():
    columns, rows = int(sys.argv[1]), int(sys.argv[2])
    size = float(sys.argv[3]) if len(sys.argv) > 3 else 0.25
    max_speed = float(sys.argv[4]) if len(sys.argv) > 4 else 3.0
    width, height = 20.0, 12.0
    # Grid pitch: the box divided evenly, always at least one block size apart.
    pitch_x, pitch_y = width / columns, height / rows
    if pitch_x <= size or pitch_y <= size:
        sys.exit("blocks do not fit: use fewer columns or rows, or a smaller size")
    colors = ["#d04040", "#e08a30", "#e0c840", "#40a050", "#30a0a0", "#4070d0", "#9050c0"]
    state = 12345

    def rand():  # a small linear congruential generator: reproducible, no imports needed
        nonlocal state
        state = (1103515245 * state + 12345) % 2**31
        return state / 2**31

    count = columns * rows
    blocks = []
    for j in range(rows):
        for i in range(columns):
            speed = max_speed * math.sqrt(rand())
            angle = 2 * math.pi * rand()
            n = len(blocks)
            blocks.append({
                "name": "g%d" % n,
                "position": [round((i + 0.5) * pitch_x, 6), round((j + 0.5) * pitch_y, 6)],
                "size": size,
                "velocity": [round(speed * math.cos(angle), 3), round(speed * math.sin(angle), 3)],
                "mass": 1,
                "color": colors[n % len(colors)],
            })
    world = {"bounds": [0, 0, width, height], "gravity": [0, 0], "bounciness": 1,
             "method": "perfect", "dt": 1 / 60, "substeps": 1}
    description = ("%d equal blocks in random motion, bounciness 1, no gravity. Total momentum "
                   "and kinetic energy stay constant however chaotic it looks; try "
                   "move-and-correct and watch the energy drift." % count)
    print("{")
    print('  "name": %s,' % json.dumps("Gas of %d blocks" % count))
    print('  "description": %s,' % json.dumps(description))
    print("  \"world\": {\n    " + ",\n    ".join(
        "%s: %s" % (json.dumps(k), json.dumps(v)) for k, v in world.items()) + "\n  },")
    print('  "blocks": [\n    ' + ",\n    ".join(json.dumps(b) for b in blocks) + "\n  ]")
    print("}")


if __name__ == "__main__":
    main()
