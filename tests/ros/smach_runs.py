"""Running generated SMACH programs on the real SMACH, for the tests that do it by the dozen
(smach_goldens.py, smacha_corpus.py).

  needs_master(program)                 a program that imports rospy runs with a master
  run_program(ros, program)             run_smach.py PROGRAM in a session, seeded, timed out
  run_with_master(overlay, work_dir, program, fixture=None, python_path=())
                                        the same in a session of its own with a private master
                                        (and a fixture that prints FIXTURE READY)
  final_outcome(finished)               (the top machine's result, None) or (None, why)
  Outcome                               what one case came to: ok / skip / fail, reported later
  run_in_order(items, check, report)    check(item) -> Outcome, two at a time, reported in
                                        the items' order
"""
import concurrent.futures
import os

import trace_protocol
from ros_session import PYTHON, RosSession

ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "tools", "ros")
RUN_SMACH = os.path.join(ROS_TOOLS, "run_smach.py")
RUN_TIMEOUT = 40
WORKERS = 2


def needs_master(program):
    with open(program, encoding="utf-8") as f:
        return "import rospy" in f.read()


def run_program(ros, program, timeout=RUN_TIMEOUT, cwd=None):
    return ros.run([PYTHON, RUN_SMACH, program, "--seed", "0"], timeout=timeout,
                   cwd=cwd or os.path.dirname(program))


def run_with_master(overlay, work_dir, program, fixture=None, python_path=(),
                    timeout=RUN_TIMEOUT, cwd=None):
    with RosSession(overlay, work_dir) as ros:
        for folder in python_path:
            ros.add_python_path(folder)
        ros.start_master()
        if fixture:
            ros.start_fixture("fixture", [PYTHON, fixture])
        return run_program(ros, program, timeout, cwd)


def final_outcome(finished):
    """(the result {"outcome", "userdata"}, None), or (None, why) with the run's output."""
    if finished.timed_out:
        return None, "timed out after %.0f s:\n%s" % (finished.seconds,
                                                      finished.stdout + finished.stderr)
    _, result = trace_protocol.parse(finished.stdout)
    if result is None or finished.returncode != 0:
        return None, "exit %d without the outcome:\n%s" % (finished.returncode, finished.stderr)
    return result, None


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


def run_in_order(items, check, report, label_of):
    """Runs check(item) -> Outcome for the items two at a time (each is mostly waiting:
    Python start-up, ROS connections) and reports them in the items' order; an exception is
    that item's failure, the others still run."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=WORKERS) as pool:
        futures = [pool.submit(check, item) for item in items]
        for item, future in zip(items, futures):
            try:
                outcome = future.result()
            except Exception as error:
                outcome = Outcome(label_of(item), "fail", repr(error))
            outcome.report_to(report)
