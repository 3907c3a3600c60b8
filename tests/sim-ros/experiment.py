#!/usr/bin/python3
"""One of the paper's Baxter experiments, generated for SMACH or FlexBE (ROS 1), run unchanged
on the simulated Baxter over ROS (tools/baxter-ros-run), judged physically with the C++ tests'
tolerances:

  experiment.py BUILD TARGET EXPERIMENT

pick_and_place: outcome succeeded, block1's centre within 10 mm of (0.75, 0, -0.13) on every
axis. stacking, dual_arm_stacking: outcome succeeded, block2 on block1 with |dxy| < 15 mm and
|dz - 0.05| < 5 mm. Every run: exit status 0 and no Python traceback.
"""
import os
import sys

from baxter_run import (EXAMPLES, PLACED, STACKED_HEIGHT, STACKED_HORIZONTAL, Checks,
                        main_with_skip, run_on_robot, stack_errors)

PLACE = (0.75, 0.0, -0.13)


def main():
    build, target, experiment = sys.argv[1:4]
    result = run_on_robot(build, os.path.join(EXAMPLES, experiment + ".yml"), target)
    print(result.stdout)
    checks = Checks()
    checks.run_ended(target, result, "succeeded")
    if not checks.check(bool(result.report), "a scene report"):
        return checks.exit_code()
    if experiment == "pick_and_place":
        block = result.block("block1")
        error = max(abs(a - b) for a, b in zip(block, PLACE))
        checks.check(error < PLACED, "block1 placed at %s within 10 mm (%.1f mm)"
                     % (PLACE, error * 1e3))
    else:
        dxy, dz = stack_errors(result)
        checks.check(dxy < STACKED_HORIZONTAL and dz < STACKED_HEIGHT,
                     "block2 on block1: |dxy| %.1f mm, |dz - size| %.1f mm" % (dxy * 1e3, dz * 1e3))
    print("simulated %.2f s in %.2f s of wall time" % (result.report["simulated"],
                                                       result.report["wall_seconds"]))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
