#!/usr/bin/python3
"""Every FlexBE golden behavior, generated fresh for ROS 1 and executed on the real flexbe_core.

  flexbe_goldens.py SMACHAC GOLDEN_DIR        (the overlay: $SMACHAC_ROS_OVERLAY)

Each `GOLDEN_DIR/<name>.yml` that has an expected `<name>.flexbe.py` is compiled with its
`# ARGS:` and `-flexbe-ros=1` into a behaviors package (flexbe_package.py) and run by
run_flexbe.py under one private master; it must reach the outcome of its `# OUTCOME:` line,
with every state entered exited once (state packages a case's templates import, such as
import_clash's my_flexbe_states, are in GOLDEN_DIR/inputs, on PYTHONPATH). `# EXECUTE: no
(<why>)` skips a case and says why. The runs of EXTRA_RUNS then check what a case's defaults
do not show: an overridden behavior parameter reaching its state, and an autonomy level making
FlexBE ask the operator. All of it runs beside a bystander (fixtures/stray_flexbe_commands.py)
that keeps FlexBE's preempt command latched on the master's root namespace: runs share one
master, two at a time, and none may hear another's commands. The ROS 2 output is not executed (Debian 12 has no rclpy); the golden
tests check it structurally.

Prints one line per run (`ok`, `FAIL` with the reason, `skip` with why) and
`N passed, N failed, N skipped`; exit 1 on a failure, 77 when the overlay has no FlexBE.
"""
import concurrent.futures
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
STRAY_COMMANDS = os.path.join(HERE, "fixtures", "stray_flexbe_commands.py")
ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
sys.path.insert(0, ROS_TOOLS)

import flexbe_package  # noqa: E402
import trace_protocol  # noqa: E402
from report import Report as LineReport  # noqa: E402
from golden_case import cases_with_output  # noqa: E402
from ros_session import PYTHON, run_test  # noqa: E402

RUNNER = os.path.join(ROS_TOOLS, "run_flexbe.py")
RUN_TIMEOUT = 30
PARALLEL_RUNS = 2  # behaviors run at once, each its own process (most of a run is waiting)
ROS2_SKIP = ("flexbe/ros2: the ROS 2 behaviors are checked structurally only "
             "(golden/flexbe/*): Debian 12 has no rclpy to run them")


# ---------------------------------------------------------------- cases

def compile_args(args):
    """The golden's smachac arguments without its output and ROS version."""
    kept, skip_next = [], False
    for arg in args:
        if skip_next or arg.startswith("-flexbe-ros="):
            skip_next = False
        elif arg == "-o":
            skip_next = True
        else:
            kept.append(arg)
    return kept


def golden_cases(golden_dir):
    return cases_with_output(golden_dir, ".flexbe.py")


# ---------------------------------------------------------------- checks of one run

def unbalanced(events):
    """Why the enter/exit events do not pair up, or None."""
    active = []
    for event in events:
        if event["event"] == "enter":
            active.append(event["state"])
        elif event["state"] not in active:
            return "exit of %s, which was not entered" % event["state"]
        else:
            active.remove(event["state"])
    return "never exited: " + ", ".join(active) if active else None


def requests(stdout):
    marker = "SMACHAC-FLEXBE-REQUEST "
    return [json.loads(line[line.index(marker) + len(marker):])
            for line in stdout.splitlines() if marker in line]


def failure(finished, expected_outcome):
    """Why a finished run failed, or None."""
    if finished.timed_out:
        return "no outcome within %d s (stopped)" % RUN_TIMEOUT
    events, result = trace_protocol.parse(finished.stdout)
    if finished.returncode != 0 or result is None:
        lines = finished.stderr.strip().splitlines()
        return "exit %d: %s" % (finished.returncode, lines[-1] if lines else "no output")
    if expected_outcome and result["outcome"] != expected_outcome:
        return "outcome %s, expected %s" % (result["outcome"], expected_outcome)
    return unbalanced(events)


# ---------------------------------------------------------------- extra runs

def logged(text, absent):
    def check(finished):
        if text not in finished.stdout:
            return "the log does not show %r" % text
        if absent in finished.stdout:
            return "the log still shows the default %r" % absent
        return None
    return check


def requested(expected):
    def check(finished):
        got = [(r["state"], r["outcome"]) for r in requests(finished.stdout)]
        return None if got == expected else "operator requests %s, expected %s" % (got, expected)
    return check


def no_requests(finished):
    got = requests(finished.stdout)
    return "operator requests at flexbe_testing's level 255: %s" % got if got else None


# (case, what, runner arguments, outcome, check of the finished run)
EXTRA_RUNS = [
    ("behavior_parameters", "parameter message=changed reaches LogState",
     ["--param", "message=changed"], "finished",
     logged("Behavior Hint: changed", "Behavior Hint: hello")),
    ("autonomy", "autonomy 255 (flexbe_testing's): WAIT's done passes without the operator",
     ["--seed", "2"], "finished", no_requests),
    ("autonomy", "autonomy High: WAIT's done (High) needs the operator, RANDOM's a (Low) not",
     ["--autonomy", "2", "--seed", "2"], "finished", requested([("WAIT", "done")])),
]


# ---------------------------------------------------------------- running

class Report(LineReport):
    behaviors = 0  # executed, embedded ones included


class Run:
    """One execution of a generated behavior and what it must show."""

    def __init__(self, label, package, arguments, outcome, check=None):
        self.label, self.package, self.arguments = label, package, arguments
        self.outcome, self.check = outcome, check

    def start(self, ros):
        env = ros.namespaced_env()  # PARALLEL_RUNS at a time
        for variable in ("PYTHONPATH", "ROS_PACKAGE_PATH"):
            env[variable] = self.package.workspace + os.pathsep + env[variable]
        env["PYTHONPATH"] += os.pathsep + self.package.inputs  # the cases' own state packages
        argv = [PYTHON, RUNNER, self.package.top[0]] + self.arguments
        return ros.processes.run(argv, env, RUN_TIMEOUT, cwd=self.package.workspace)

    def report(self, finished, report):
        why = failure(finished, self.outcome) or (self.check and self.check(finished))
        if why:
            report.fail(self.label, why)
            return
        outcome = trace_protocol.parse(finished.stdout)[1]["outcome"]
        embedded = self.package.embedded if self.check is None else []
        report.behaviors += 0 if self.check else 1 + len(embedded)
        report.ok(self.label, "outcome %s (%.1f s)%s" % (
            outcome, finished.seconds,
            " with embedded " + ", ".join(embedded) if embedded else ""))


def generated(smachac, case, work, report):
    """The case's package, or None (reported) when it is not run."""
    label = "flexbe/" + case.name
    if case.no_execute:
        report.skip(label, case.no_execute)
        return None
    try:
        package = flexbe_package.generate(smachac, case.name + ".yml", compile_args(case.args),
                                          case.folder, os.path.join(work, case.name))
    except flexbe_package.GenerateError as error:
        report.fail(label, str(error))
        return None
    if len(package.top) != 1:
        report.fail(label, "expected one top behavior, the manifests give %s" % package.top)
        return None
    package.inputs = os.path.join(case.folder, "inputs")
    return package


def planned_runs(smachac, golden_dir, work, report):
    runs, packages = [], {}
    for case in golden_cases(golden_dir):
        packages[case.name] = generated(smachac, case, work, report)
        if packages[case.name] is not None:
            runs.append(Run("flexbe/" + case.name, packages[case.name], [], case.outcome))
    for name, what, arguments, outcome, check in EXTRA_RUNS:
        label = "flexbe/%s [%s]" % (name, what)
        if packages.get(name) is None:
            report.skip(label, "the case is not run")
        else:
            runs.append(Run(label, packages[name], arguments, outcome, check))
    return runs


def run_all(ros, smachac, golden_dir, work, report):
    runs = planned_runs(smachac, golden_dir, work, report)
    ros.start_fixture("stray_flexbe_commands", [PYTHON, STRAY_COMMANDS])
    with concurrent.futures.ThreadPoolExecutor(PARALLEL_RUNS) as pool:
        for run, finished in zip(runs, pool.map(lambda r: r.start(ros), runs)):
            run.report(finished, report)
    report.skip(*ROS2_SKIP.split(": ", 1))


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    smachac, golden_dir = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    report = Report()

    def body(ros, work):
        run_all(ros, smachac, golden_dir, work, report)
        print("%d behaviors executed, embedded ones included" % report.behaviors)
        return report.close()

    return run_test("flexbe-goldens", ["flexbe"], body)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
