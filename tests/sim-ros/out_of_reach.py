#!/usr/bin/python3
"""A block out of the arm's reach (x = 1.4 m) on the simulated Baxter over ROS: the SMACH and
FlexBE programs of pick_and_place.yml end `aborted` at the first IK (the IK service answers
isValid false), exit 0 and print no traceback; the block stays where it was loaded.

  out_of_reach.py BUILD WORK_DIR
"""
import os
import sys

from baxter_run import EXAMPLES, Checks, main_with_skip, run_on_robot, write_variant

FAR_X = 1.4


def main():
    build, work_dir = sys.argv[1:3]
    script = write_variant(os.path.join(EXAMPLES, "pick_and_place.yml"),
                           [("block_model_%s: [[0.7," % kind, "block_model_%s: [[%r," % (kind, FAR_X))
                            for kind in ("pose_base", "pick_pose")], work_dir)
    checks = Checks()
    for target in ("smach", "flexbe"):
        result = run_on_robot(build, script, target)
        print(result.stdout)
        checks.run_ended(target, result, "aborted")
        checks.check("exit PICK_BLOCK/IK_PICK_BLOCK_HOVER_POSE -> aborted" in result.stdout,
                     "%s: aborted at the first IK" % target)
        if result.report:
            x = result.block("block1")[0]
            checks.check(abs(x - FAR_X) < 0.005, "%s: block1 left at x = %.3f" % (target, x))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
