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
import concurrent.futures
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
sys.path[:0] = [HERE, ROS_TOOLS]

import trace_protocol  # noqa: E402
from golden_case import smach_cases  # noqa: E402
from report import Report  # noqa: E402
from ros_session import PYTHON, RosSession, run_test  # noqa: E402

RUN_SMACH = os.path.join(ROS_TOOLS, "run_smach.py")
FIXTURES = os.path.join(HERE, "fixtures")
RUN_TIMEOUT = 40
WORKERS = 2


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


def needs_master(program):
    with open(program, encoding="utf-8") as f:
        return "import rospy" in f.read()


def fixture_of(case):
    path = os.path.join(FIXTURES, "golden_%s.py" % case.name)
    return path if os.path.exists(path) else None


def run_program(ros, program):
    return ros.run([PYTHON, RUN_SMACH, program, "--seed", "0"], timeout=RUN_TIMEOUT,
                   cwd=os.path.dirname(program))


def run_with_master(overlay, work_dir, case, program):
    with RosSession(overlay, work_dir) as ros:
        ros.start_master()
        fixture = fixture_of(case)
        if fixture:
            ros.start_fixture("fixture", [PYTHON, fixture])
        return run_program(ros, program)


def verdict(case, finished):
    """(what it reached, None) or (None, why it failed, details)."""
    if finished.timed_out:
        return None, "timed out after %g s" % RUN_TIMEOUT, finished.stdout + finished.stderr
    _, result = trace_protocol.parse(finished.stdout)
    if result is None or finished.returncode != 0:
        return None, "exit %d without the outcome" % finished.returncode, finished.stderr
    if result["outcome"] != case.outcome:
        return None, "outcome %s, expected %s" % (result["outcome"], case.outcome), finished.stderr
    return "outcome " + result["outcome"], None, ""


class Outcome:
    """What one case came to, reported once all cases ran (in the cases' order)."""

    def __init__(self, label, kind, text, seconds=None, details=""):
        self.label, self.kind, self.text, self.seconds, self.details = \
            label, kind, text, seconds, details

    def report_to(self, report):
        if self.kind == "ok":
            report.ok(self.label, self.text, self.seconds)
        elif self.kind == "skip":
            report.skip(self.label, self.text)
        else:
            report.fail(self.label, self.text, self.seconds, self.details)


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
        finished = run_with_master(overlay, case_dir, case, program)
    else:
        finished = run_program(core, program)
    reached, why, details = verdict(case, finished)
    if why:
        return Outcome(label, "fail", why, time.monotonic() - began, details)
    return Outcome(label, "ok", reached, time.monotonic() - began)


def check_all(cases, smachac, overlay, core, work_dir, report):
    """Runs the cases two at a time (each is mostly waiting: Python start-up, ROS
    connections) and reports them in order."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=WORKERS) as pool:
        futures = [pool.submit(check_case, case, smachac, overlay, core, work_dir)
                   for case in cases]
        for case, future in zip(cases, futures):
            try:
                outcome = future.result()
            except Exception as error:  # a broken case is a failure; the others still run
                outcome = Outcome("smach/" + case.name, "fail", repr(error))
            outcome.report_to(report)


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    smachac, golden_dir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    overlay = os.environ.get("SMACHAC_ROS_OVERLAY", "")
    report = Report()

    def body(core, work_dir):  # core programs share this session; ROS ones get their own
        check_all(smach_cases(golden_dir), smachac, overlay, core, work_dir, report)
        return report.close()

    return run_test("smach-goldens", ["smach"], body, master=False)


if __name__ == "__main__":
    sys.exit(main())
