#!/usr/bin/python3
"""The Baxter states' failures and an offset's rotation on the simulated Baxter over ROS, for
SMACH and FlexBE (cases/state_edges.yml): spawning a model the world does not have, closing
the gripper on nothing when a grasp is expected, an unknown gripper command, six joint
positions for a seven-joint arm and a pose out of reach must each end `aborted` (the script
leads on from there); then IK for a pose plus an offset that turns the gripper 45° about its
axis, the move there and the endpoint read back.

  state_edges.py BUILD

Each target: exit 0, no traceback, every failing state aborted and the machine succeeded, the
left endpoint at the posed point plus the offset (within 1 cm) and turned as the offset's
rotation composed after the pose's (within 3°).
"""
import math
import os
import sys

from baxter_run import HERE, Checks, main_with_skip, run_on_robot

SCRIPT = os.path.join(HERE, "cases", "state_edges.yml")
FAILING = ["SPAWN_UNKNOWN_MODEL", "CLOSE_ON_NOTHING", "UNKNOWN_GRIPPER_COMMAND",
           "SIX_JOINT_POSITIONS", "IK_OUT_OF_REACH"]
POSITION = (0.7, 0.15, 0.15)
POSE_ROTATION = (0.0, 1.0, 0.0, 0.0)  # x, y, z, w: the gripper pointing down
TURN = (0.0, 0.0, 0.38268, 0.92388)  # 45 degrees about the gripper's axis


def product(a, b):
    """The Hamilton product a * b of quaternions given as (x, y, z, w)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def angle_between(a, b):
    dot = abs(sum(x * y for x, y in zip(a, b))) / math.sqrt(sum(x * x for x in a) *
                                                             sum(y * y for y in b))
    return 2.0 * math.acos(min(1.0, dot))


def main():
    build = sys.argv[1]
    checks = Checks()
    for target in ("smach", "flexbe"):
        result = run_on_robot(build, SCRIPT, target)
        print(result.stdout)
        checks.run_ended(target, result, "succeeded")
        for state in FAILING:
            checks.check("exit %s -> aborted" % state in result.stdout,
                         "%s: %s aborted" % (target, state))
        if not checks.check(bool(result.report), "%s: a scene report" % target):
            continue
        endpoint = result.report["endpoints"]["left"]
        distance = math.dist(endpoint[:3], POSITION)
        checks.check(distance < 0.01, "%s: the endpoint at %s (%.1f mm off)"
                     % (target, POSITION, distance * 1e3))
        turned = angle_between(endpoint[3:], product(POSE_ROTATION, TURN))
        checks.check(math.degrees(turned) < 3.0, "%s: the gripper turned by the offset "
                     "(%.2f° off)" % (target, math.degrees(turned)))
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
