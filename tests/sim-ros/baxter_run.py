"""What the sim-ros tests share: running tools/baxter-ros-run as a user would and reading what
it reports, and the physical checks of the C++ Baxter tests.

    result = run_on_robot(build, script, target="smach", extra=["--preempt-at", "A/B"])
    result.outcome, result.report["blocks"], result.report["max_joint_speed"], result.stdout

A run the machine cannot do (no ROS, framework or Baxter SDK here) raises Skip with the
runner's reason; a test prints it and exits 77 (ctest: skipped).
"""
import json
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "ros"))

from report import Report  # noqa: E402
RUNNER = os.path.join(ROOT, "tools", "baxter-ros-run")
EXAMPLES = os.path.join(ROOT, "examples", "baxter")
SKIPPED = 77
BLOCK_SIZE = 0.05
STACKED_HORIZONTAL = 0.015  # m, |dxy| of stacked blocks (the C++ tests' threshold)
STACKED_HEIGHT = 0.005  # m, |dz - block size|
PLACED = 0.010  # m per axis, a placed block's distance from its place (the C++ test's)
RUN_TIMEOUT = 300  # s of wall time for one run


class Skip(Exception):
    """The run cannot be done here; the message says why."""


class Result:
    def __init__(self, returncode, stdout, report):
        self.returncode = returncode
        self.stdout = stdout
        self.report = report
        found = re.findall(r"^outcome: (\S+)$", stdout, re.MULTILINE)
        self.outcome = found[-1] if found else None

    def block(self, name):
        """A block's centre [x, y, z] in the base frame."""
        return self.report["blocks"][name][:3]


def runner_argv(build, script, target, extra, report_path):
    return [sys.executable, RUNNER, "--target", target, "--build", build,
            "--report-json", report_path, "-S", EXAMPLES] + list(extra) + [script]


def finish(process, stdout, report_path):
    if process.returncode == SKIPPED:
        raise Skip(stdout.strip().splitlines()[-1] if stdout.strip() else "skipped")
    report = {}
    if os.path.exists(report_path):
        with open(report_path, encoding="utf-8") as f:
            report = json.load(f)
    return Result(process.returncode, stdout, report)


def run_on_robot(build, script, target="smach", extra=(), interrupt_at=None):
    """Runs the runner to its end; with interrupt_at, sends it SIGINT (as Ctrl-C would) when
    its output shows that state entered."""
    with tempfile.TemporaryDirectory(prefix="sim-ros-") as work:
        report_path = os.path.join(work, "report.json")
        process = subprocess.Popen(runner_argv(build, script, target, extra, report_path),
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   errors="replace")
        lines = []
        deadline = time.monotonic() + RUN_TIMEOUT
        try:
            for line in process.stdout:
                lines.append(line)
                if interrupt_at is not None and line.rstrip().endswith("enter " + interrupt_at):
                    process.send_signal(signal.SIGINT)
                    interrupt_at = None
                if time.monotonic() > deadline:
                    break
        finally:
            if process.poll() is None and time.monotonic() > deadline:
                process.send_signal(signal.SIGINT)
                process.send_signal(signal.SIGINT)
            process.wait()
        return finish(process, "".join(lines), report_path)


def write_variant(source, replacements, work_dir):
    """Writes source with each (old, new) replaced (each old must occur) into work_dir under
    the same name; returns the new path."""
    with open(source, encoding="utf-8") as f:
        text = f.read()
    for old, new in replacements:
        if old not in text:
            raise SystemExit("%s no longer holds %r" % (source, old))
        text = text.replace(old, new)
    os.makedirs(work_dir, exist_ok=True)
    path = os.path.join(work_dir, os.path.basename(source))
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def horizontal(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def stack_errors(result):
    """(|dxy|, |dz - size|) of block2 on block1."""
    upper, lower = result.block("block2"), result.block("block1")
    return horizontal(upper, lower), abs(upper[2] - lower[2] - BLOCK_SIZE)


class Checks(Report):
    """The ros tests' report (`ok` / `FAIL` lines, the closing count), fed by conditions."""

    def check(self, condition, description):
        case, _, what = description.partition(": ")
        (self.ok if condition else self.fail)(case, what)
        return condition

    def run_ended(self, label, result, outcome):
        """The checks of every run: exit status 0, no Python traceback, the outcome."""
        self.check(result.returncode == 0, "%s: exit status 0 (%s)" % (label, result.returncode))
        self.check("Traceback" not in result.stdout, "%s: no Python traceback" % label)
        return self.check(result.outcome == outcome, "%s: outcome %s (%s)"
                          % (label, outcome, result.outcome))

    def exit_code(self):
        return self.close()


def main_with_skip(body):
    """Runs body() -> exit code; a Skip prints its reason and exits 77."""
    try:
        sys.exit(body())
    except Skip as why:
        print("skip: %s" % why)
        sys.exit(SKIPPED)
