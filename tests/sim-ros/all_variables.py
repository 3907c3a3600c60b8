#!/usr/bin/python3
"""Every Baxter template once, every variable given (tests/golden/*_baxter/all_variables.yml,
the same script for both targets), on the simulated Baxter over ROS, for SMACH and FlexBE:
a model loaded from its model_path in a remapped frame, IK with an offset, a joint move and
a joint trajectory (the follow_joint_trajectory action) at once in a Concurrence, a close on
nothing that expects no grasp, and the endpoint read back. The script's model is renamed
`block1` (the scene has no body "block 'one'") and its model file is the project's.

  all_variables.py BUILD WORK_DIR

Each target: exit 0, outcome succeeded, every state succeeded, block1 where the script loads
it, the left arm at the move's goal and the right at the trajectory's last point (within the
SDK's 0.5° per joint).
"""
import math
import os
import sys

from baxter_run import ROOT, Checks, main_with_skip, run_on_robot, write_variant

SCRIPT = os.path.join(ROOT, "tests", "golden", "smach_baxter", "all_variables.yml")
MODEL = os.path.join(ROOT, "sim", "ros", "baxter_sim_examples", "models", "block", "model.urdf")
LOADED = (0.7, 0.15, -0.13)
GOALS = {"left": [-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5],  # MOVE's positions
         "right": [0.0, -0.5, 1.0, 1.5, 0.0, 1.0, 0.0]}  # FOLLOW's last point
TOLERANCE = 0.0088  # rad, the SDK's threshold (0.5°) and a little


def main():
    build, work_dir = sys.argv[1:3]
    script = write_variant(SCRIPT, [("model_name: \"block 'one'\"", "model_name: block1"),
                                    ("model_path: /tmp/block.urdf", "model_path: " + MODEL)],
                           work_dir)
    checks = Checks()
    for target in ("smach", "flexbe"):
        result = run_on_robot(build, script, target)
        print(result.stdout)
        checks.run_ended(target, result, "succeeded")
        for state in ("ARMS/MOVE", "ARMS/FOLLOW", "GRIP", "READ"):
            checks.check("exit %s -> succeeded" % state in result.stdout,
                         "%s: %s succeeded" % (target, state))
        if not checks.check(bool(result.report), "%s: a scene report" % target):
            continue
        distance = math.dist(result.block("block1"), LOADED)
        checks.check(distance < 0.005, "%s: block1 loaded at %s (%.1f mm off)"
                     % (target, LOADED, distance * 1e3))
        for side, goal in GOALS.items():
            error = max(abs(a - b) for a, b in zip(result.report["joints"][side], goal))
            checks.check(error < TOLERANCE, "%s: the %s arm at its goal (%.4f rad off)"
                         % (target, side, error))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
