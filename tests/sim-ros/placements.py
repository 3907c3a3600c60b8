#!/usr/bin/python3
"""Writes seeded random block placements of the stacking experiment as scripts, for the
sim-ros tests and the C++ programs they are compared with (run at configure time):

  placements.py STACKING.yml OUT_DIR COUNT SEED

Each placement moves both blocks of examples/baxter/stacking.yml up to ±3 cm in x and y from
the script's poses, with the pick poses following the blocks (as a perception step would give
them); placements whose blocks lie closer than 8 cm (the fingers need room) are drawn again,
as tests/sim's random stacking test does. OUT_DIR gets placement_<i>.yml (i = 0 .. COUNT-1),
the script with the four poses replaced, and placements.json, the list of [x1, y1, x2, y2].
"""
import json
import math
import os
import random
import re
import sys

SPREAD = 0.03
MIN_SEPARATION = 0.08
BLOCKS = {1: (0.7, 0.15), 2: (0.8, 0.15)}
# The lines of a block's model pose and pick pose: `block_model_<n>_<kind>: [[x, y, z], ...`
POSE_LINE = re.compile(r"(block_model_(\d)_(pose_base|pick_pose): \[\[)([-0-9.]+), ([-0-9.]+),")


def draw(generator):
    while True:
        placement = [BLOCKS[1][0] + generator.uniform(-SPREAD, SPREAD),
                     BLOCKS[1][1] + generator.uniform(-SPREAD, SPREAD),
                     BLOCKS[2][0] + generator.uniform(-SPREAD, SPREAD),
                     BLOCKS[2][1] + generator.uniform(-SPREAD, SPREAD)]
        x1, y1, x2, y2 = placement
        if math.hypot(x1 - x2, y1 - y2) >= MIN_SEPARATION:
            return [round(v, 4) for v in placement]


def placed_script(text, placement):
    def replace(match):
        block = int(match.group(2))
        x, y = placement[2 * (block - 1):2 * block]
        return "%s%r, %r," % (match.group(1), x, y)

    script, count = POSE_LINE.subn(replace, text)
    if count != 4:
        raise SystemExit("placements.py: expected 4 block poses in the script, found %d" % count)
    return script


def main():
    if len(sys.argv) != 5:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    source, out_dir, count, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    with open(source, encoding="utf-8") as f:
        text = f.read()
    generator = random.Random(seed)
    placements = [draw(generator) for _ in range(count)]
    os.makedirs(out_dir, exist_ok=True)
    for i, placement in enumerate(placements):
        with open(os.path.join(out_dir, "placement_%d.yml" % i), "w", encoding="utf-8") as f:
            f.write(placed_script(text, placement))
    with open(os.path.join(out_dir, "placements.json"), "w", encoding="utf-8") as f:
        json.dump(placements, f)
        f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
