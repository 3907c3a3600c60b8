#!/usr/bin/python3
"""Every SMACH golden case compiled fresh and executed on the real SMACH (label ros).

  smach_goldens.py SMACHAC GOLDEN_DIR        the overlay is $SMACHAC_ROS_OVERLAY

For each GOLDEN_DIR/<name>.yml that has a <name>.smach.py: smachac compiles it with the
case's `# ARGS:` in its folder, the output must equal the expected file, and run_smach.py
runs it as generated on the real SMACH: a core program without a master, a ROS program
(`import rospy`) with a private master and, when fixtures/golden_<name>.py exists, that
fixture's servers. The top state machine must reach the case's `# OUTCOME:`; a case marked
`# EXECUTE: no (why)` is skipped with its reason. Prints one line per case and the closing
`N passed, N failed, N skipped`; exits 77 (skip) when the overlay has no SMACH.
"""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
sys.path[:0] = [HERE, ROS_TOOLS]

from golden_case import smach_cases  # noqa: E402
from report import Report  # noqa: E402
from ros_session import run_test  # noqa: E402
from smach_runs import (Outcome, final_outcome, needs_master, run_in_order,  # noqa: E402
                        run_program, run_with_master)

FIXTURES = os.path.join(HERE, "fixtures")


def compile_case(case, smachac, program):
    """Writes the case's fresh output to program; None, or why it is not the golden."""
    result = subprocess.run(case.smachac_argv(smachac), cwd=case.folder, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", timeout=60)
    if result.returncode != 0:
        return "smachac exited %d: %s" % (result.returncode, result.stderr.strip()[-400:])
    with open(program, "w", encoding="utf-8", newline="") as f:
        f.write(result.stdout)
    if result.stdout != case.expected():
        return "differs from %s (regenerate and review it)" % os.path.basename(case.expected_python)
    return None


def fixture_of(case):
    path = os.path.join(FIXTURES, "golden_%s.py" % case.name)
    return path if os.path.exists(path) else None


def check_case(case, smachac, overlay, core, work_dir):
    label = "smach/" + case.name
    began = time.monotonic()
    program = os.path.join(work_dir, case.name + ".py")
    problem = compile_case(case, smachac, program)
    if problem:
        return Outcome(label, "fail", problem, time.monotonic() - began)
    if case.no_execute:
        return Outcome(label, "skip", case.no_execute)
    if case.outcome is None:
        return Outcome(label, "fail", "the case declares no `# OUTCOME:`")
    if needs_master(program):
        case_dir = os.path.join(work_dir, case.name)
        os.makedirs(case_dir)
        finished = run_with_master(overlay, case_dir, program, fixture_of(case))
    else:
        finished = run_program(core, program)
    result, why = final_outcome(finished)
    seconds = time.monotonic() - began
    if why:
        why, _, details = why.partition("\n")
        return Outcome(label, "fail", why, seconds, details)
    if result["outcome"] != case.outcome:
        return Outcome(label, "fail", "outcome %s, expected %s" % (result["outcome"], case.outcome),
                       seconds, finished.stderr)
    return Outcome(label, "ok", "outcome " + result["outcome"], seconds)


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    smachac, golden_dir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    overlay = os.environ.get("SMACHAC_ROS_OVERLAY", "")
    report = Report()

    def body(core, work_dir):  # core programs share this session; ROS ones get their own
        run_in_order(smach_cases(golden_dir),
                     lambda case: check_case(case, smachac, overlay, core, work_dir), report,
                     lambda case: "smach/" + case.name)
        return report.close()

    return run_test("smach-goldens", ["smach"], body, master=False)


if __name__ == "__main__":
    sys.exit(main())
