#!/usr/bin/python3
"""Preempting the dual-arm stacking program on the simulated Baxter over ROS while both arms
move to their first blocks: by SMACH's preempt request (SIGUSR1 through baxter-ros-run
--preempt-at) and by SIGINT (Ctrl-C on baxter-ros-run, which passes it on). Both arms stop:
after the runner's settling second every joint is slower than STOPPED, and no block has
moved; the program exits 0 with outcome preempted (request) or aborted (SIGINT: rospy shuts
down, and the Baxter SDK's waits end the states).

  preempt.py BUILD
"""
import math
import os
import sys

from baxter_run import EXAMPLES, Checks, main_with_skip, run_on_robot

STATE = "PICK_BLOCKS/PICK_BLOCK_1/PICK_BLOCK/MOVE_TO_PICK_BLOCK_HOVER_POSE"
STOPPED = 0.01  # rad/s
LOADED = {"block1": (0.7, 0.15), "block2": (0.7, -0.2)}  # where dual_arm_stacking.yml puts them
HOVER = {"left": (0.7, 0.15, 0.02), "right": (0.7, -0.2, 0.02)}  # the moves that were preempted


def check_stopped(checks, how, result, outcome):
    checks.run_ended(how, result, outcome)
    checks.check("exit PICK_BLOCKS -> %s" % outcome in result.stdout,
                 "%s: PICK_BLOCKS ended %s" % (how, outcome))
    if not checks.check(bool(result.report), "%s: a scene report" % how):
        return
    speed = result.report["max_joint_speed"]
    checks.check(speed < STOPPED, "%s: both arms stopped (fastest joint %.4f rad/s)" % (how, speed))
    for side, hover in HOVER.items():
        distance = math.dist(result.report["endpoints"][side][:3], hover)
        checks.check(distance > 0.05, "%s: the %s arm stopped %.0f mm short of its hover pose"
                     % (how, side, distance * 1e3))
    for block, (x, y) in LOADED.items():
        at = result.block(block)
        checks.check(abs(at[0] - x) < 0.005 and abs(at[1] - y) < 0.005,
                     "%s: %s still at (%.3f, %.3f)" % (how, block, at[0], at[1]))


def main():
    build = sys.argv[1]
    script = os.path.join(EXAMPLES, "dual_arm_stacking.yml")
    checks = Checks()
    requested = run_on_robot(build, script, extra=["--preempt-at", STATE])
    print(requested.stdout)
    check_stopped(checks, "preempt request", requested, "preempted")
    interrupted = run_on_robot(build, script, interrupt_at=STATE)
    print(interrupted.stdout)
    check_stopped(checks, "SIGINT", interrupted, "aborted")
    return checks.exit_code()


if __name__ == "__main__":
    main_with_skip(main)
