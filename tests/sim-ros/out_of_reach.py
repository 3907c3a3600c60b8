#!/usr/bin/python3
"""A block out of the arm's reach (x = 1.4 m) on the simulated Baxter over ROS: the SMACH and
FlexBE programs of pick_and_place.yml end `aborted` at the first IK (the IK service answers
isValid false), exit 0 and print no traceback; the block stays where it was loaded.

  out_of_reach.py BUILD WORK_DIR
"""
import os
import sys

from baxter_run import EXAMPLES, Checks, main_with_skip, run_on_robot

FAR_X = 1.4


def far_script(work_dir):
    with open(os.path.join(EXAMPLES, "pick_and_place.yml"), encoding="utf-8") as f:
        text = f.read()
    for kind in ("pose_base", "pick_pose"):
        text = text.replace("block_model_%s: [[0.7," % kind, "block_model_%s: [[%r," % (kind, FAR_X))
    if text.count("[[%r," % FAR_X) != 2:
        raise SystemExit("out_of_reach.py: pick_and_place.yml no longer has the block poses")
    path = os.path.join(work_dir, "pick_far.yml")
    os.makedirs(work_dir, exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def main():
    build, work_dir = sys.argv[1:3]
    script = far_script(work_dir)
    checks = Checks()
    for target in ("smach", "flexbe"):
        result = run_on_robot(build, script, target)
        print(result.stdout)
        checks.check(result.returncode == 0, "%s: exit status 0 (%s)" % (target, result.returncode))
        checks.check("Traceback" not in result.stdout, "%s: no Python traceback" % target)
        checks.check(result.outcome == "aborted", "%s: outcome aborted (%s)"
                     % (target, result.outcome))
        checks.check("exit PICK_BLOCK/IK_PICK_BLOCK_HOVER_POSE -> aborted" in result.stdout,
                     "%s: aborted at the first IK" % target)
        if result.report:
            x = result.block("block1")[0]
            checks.check(abs(x - FAR_X) < 0.005, "%s: block1 left at x = %.3f" % (target, x))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
