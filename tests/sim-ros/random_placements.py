#!/usr/bin/python3
"""The stacking experiment's SMACH program for seeded random block placements on the simulated
Baxter over ROS, each compared with the C++ program generated from the same script:

  random_placements.py BUILD PLACEMENTS_DIR CPP_PROGRAM_PREFIX FIRST LAST

PLACEMENTS_DIR holds placement_<i>.yml and placements.json (placements.py, at configure
time); <CPP_PROGRAM_PREFIX><i> is the C++ program of placement_<i>.yml. For each placement
from FIRST to LAST (two ctest entries share the ten, so that they run side by side):
the SMACH program ends succeeded with block2 on block1 (|dxy| < 15 mm, |dz - 0.05| < 5 mm),
the C++ program ends the same way, and each block rests within SAME_PLACE of where the C++
program left it.
"""
import json
import math
import os
import re
import subprocess
import sys

from baxter_run import (STACKED_HEIGHT, STACKED_HORIZONTAL, Checks, horizontal, main_with_skip,
                        run_on_robot, stack_errors)

SAME_PLACE = 0.005  # m: where both programs leave a block (measured: at most 2.8 mm apart;
#                     the SDK ends a move within 0.5° of each joint's goal, the C++ states on it)
NUMBER = r"(-?[0-9]+\.[0-9]+)"


def cpp_run(program):
    """(outcome, {block: [x, y, z]}) of a C++ Baxter program's report."""
    finished = subprocess.run([program, "--robot-quiet"], stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=300)
    outcome = re.search(r"^outcome: (\S+)$", finished.stdout, re.MULTILINE)
    blocks = {name: [float(v) for v in values] for name, *values in re.findall(
        r"(block\d) at \(%s, %s, %s\)" % (NUMBER, NUMBER, NUMBER), finished.stdout)}
    return (outcome.group(1) if outcome else None), blocks


def main():
    build, folder, prefix = sys.argv[1:4]
    first, last = int(sys.argv[4]), int(sys.argv[5])
    with open(os.path.join(folder, "placements.json"), encoding="utf-8") as f:
        placements = json.load(f)
    checks = Checks()
    worst_stack, worst_difference = 0.0, 0.0
    for i in range(first, last + 1):
        placement = placements[i]
        name = "placement %d %s" % (i, placement)
        result = run_on_robot(build, os.path.join(folder, "placement_%d.yml" % i))
        if not checks.check(result.outcome == "succeeded" and bool(result.report),
                            "%s: SMACH outcome succeeded (%s)" % (name, result.outcome)):
            print(result.stdout)
            continue
        dxy, dz = stack_errors(result)
        worst_stack = max(worst_stack, dxy)
        checks.check(dxy < STACKED_HORIZONTAL and dz < STACKED_HEIGHT,
                     "%s: SMACH stacked, |dxy| %.1f mm, |dz - size| %.1f mm"
                     % (name, dxy * 1e3, dz * 1e3))
        outcome, blocks = cpp_run(prefix + str(i))
        checks.check(outcome == "succeeded", "%s: C++ outcome %s" % (name, outcome))
        for block in ("block1", "block2"):
            if block not in blocks:
                checks.check(False, "%s: C++ reports %s" % (name, block))
                continue
            ros, cpp = result.block(block), blocks[block]
            difference = math.dist(ros, cpp)
            worst_difference = max(worst_difference, difference)
            checks.check(difference < SAME_PLACE,
                         "%s: %s %.1f mm from the C++ program's (|dxy| %.1f mm)"
                         % (name, block, difference * 1e3, horizontal(ros, cpp) * 1e3))
    print("worst |dxy| of the stack %.1f mm; worst distance from the C++ program's blocks %.1f mm"
          % (worst_stack * 1e3, worst_difference * 1e3))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
