#!/usr/bin/python3
"""SMACHA's public test corpus compiled with the built-in templates and run on the real SMACH
(label ros).

  smacha_corpus.py SMACHAC [SMACHA_DIR]   SMACHA_DIR: SMACHA's sources (smacha/, smacha_ros/),
                                          by default the frameworks folder's checkout `smacha`
                                          (tools/frameworks); the overlay is $SMACHAC_ROS_OVERLAY

Every script under SMACHA_DIR/{smacha,smacha_ros}/test/smacha_scripts/<group>/ is compiled
with `-target=smach`, the built-in templates and what SMACHA's own tests give it (the test
templates of smacha_templates/<group> with -I, the script folder with -S), and run as
generated with run_smach.py: ROS programs with a private master, the executive-tutorial ones
with the messages SMACHA's smacha_ros package builds for them (GripperSrv, Test.action).
Each must reach the outcome smacha_corpus_expected.py names for it, or be rejected there
with the diagnostic named (a script SMACHA compiles into a program SMACH refuses). The bag
files of the rosbag scripts (absolute paths in /tmp, as written in the scripts) are read
back, must hold the recorded topics, and are deleted. Sub-scripts are not programs: each is
reported with the scripts that include it. Prints one line per script and the closing
`N passed, N failed, N skipped`; exits 77 (skip) when the corpus or SMACH is absent.
"""
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
sys.path[:0] = [HERE, ROS_TOOLS]

import corpus_bags  # noqa: E402
import frameworks  # noqa: E402
from overlay import Overlay, unavailable  # noqa: E402
from report import Report  # noqa: E402
from ros_session import SKIPPED, run_test  # noqa: E402
from smach_runs import (Outcome, final_outcome, needs_master, run_in_order,  # noqa: E402
                        run_program, run_with_master)
from smacha_corpus_expected import EXPECTED, REJECTED  # noqa: E402

PACKAGES = ("smacha", "smacha_ros")
GROUPS = ("smacha_test_examples", "executive_smach_tutorials")
RUN_TIMEOUT = 60  # the longest script sleeps 15 s


class Script:
    """One corpus script: its label (package/group/name), file, folders and templates."""

    def __init__(self, smacha_dir, package, group, file_name):
        test = os.path.join(smacha_dir, package, "test")
        self.folder = os.path.join(test, "smacha_scripts", group)
        self.path = os.path.join(self.folder, file_name)
        self.name = file_name[:-len(".yml")]
        self.label = "corpus/%s/%s/%s" % (package, group, self.name)
        self.key = "%s/%s/%s" % (package, group, self.name)
        self.templates = os.path.join(test, "smacha_templates", group)
        self.sub_script = False  # set by corpus(): another script includes it
        with open(self.path, encoding="utf-8") as f:
            self.text = f.read()

    def smachac_argv(self, smachac, program, flags=()):
        argv = [smachac, "-target=smach", "-S", self.folder] + list(flags)
        if os.path.isdir(self.templates):
            argv += ["-I", self.templates]
        return argv + [self.path, "-o", program]

    def includes(self, other):
        """Whether this script includes other (`script: NAME`, shorthand `S: NAME`)."""
        return re.search(r"\b(script|S)\s*:\s*['\"]?%s(\.yml)?\b" % re.escape(other.name),
                         self.text) is not None


def corpus(smacha_dir):
    scripts = []
    for package in PACKAGES:
        for group in GROUPS:
            folder = os.path.join(smacha_dir, package, "test", "smacha_scripts", group)
            if os.path.isdir(folder):
                found = [Script(smacha_dir, package, group, f)
                         for f in sorted(os.listdir(folder)) if f.endswith(".yml")]
                for script in found:
                    script.sub_script = any(other.includes(script) for other in found)
                scripts += found
    return scripts


def tutorial_messages(smacha_dir, work_dir):
    """The messages SMACHA's smacha_ros package generates for the executive tutorials
    (GripperSrv.srv, Test.action), generated as the overlay generates its own; the folder to
    put on PYTHONPATH."""
    tutorials = os.path.join(smacha_dir, "smacha_ros", "test", "executive_smach_tutorials",
                             "smach_tutorials")
    package = os.path.join(work_dir, "messages", "src", "smacha_ros")
    for kind in ("srv", "action"):
        os.makedirs(os.path.join(package, kind))
        source = os.path.join(tutorials, kind)
        for name in sorted(os.listdir(source)) if os.path.isdir(source) else []:
            shutil.copy(os.path.join(source, name), os.path.join(package, kind, name))
    overlay = Overlay(os.path.join(work_dir, "messages"))
    os.makedirs(overlay.gen)
    overlay.generate_messages("smacha_ros", package)
    return overlay.gen


def compile_script(script, smachac, program, flags=()):
    result = subprocess.run(script.smachac_argv(smachac, program, flags), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", timeout=60)
    return result.returncode, result.stderr


class Corpus:
    def __init__(self, smachac, smacha_dir, overlay, core, work_dir):
        self.smachac, self.smacha_dir, self.overlay = smachac, smacha_dir, overlay
        self.core, self.work_dir = core, work_dir
        self.messages = tutorial_messages(smacha_dir, work_dir)
        self.compiled = set()  # keys of the scripts smachac compiled
        self.reached = {}  # key: the outcome its program reached

    def check(self, script):
        if script.sub_script:
            return Outcome(script.label, "ok", "sub-script")  # reported with its includers
        began = time.monotonic()
        program = os.path.join(self.work_dir, script.key.replace("/", "__") + ".py")
        returncode, stderr = compile_script(script, self.smachac, program)
        seconds = time.monotonic() - began
        rejected = REJECTED.get(script.key)
        if rejected:
            return self.rejected(script, program, returncode, stderr, began, *rejected)
        if returncode != 0:
            return Outcome(script.label, "fail", "smachac exited %d" % returncode, seconds,
                           stderr)
        self.compiled.add(script.key)
        return self.run(script, program, began)

    def rejected(self, script, program, returncode, stderr, began, kind, error, why):
        """A script smachac must reject with kind; compiled anyway (-Wno-error=KIND), SMACH
        itself must refuse the program: it logs error and its execute() returns None."""
        if returncode != 1 or "[%s]" % kind not in stderr:
            return Outcome(script.label, "fail", "expected a rejection [%s], smachac exited %d"
                           % (kind, returncode), time.monotonic() - began, stderr)
        returncode, stderr = compile_script(script, self.smachac, program,
                                            ["-Wno-error=" + kind])
        if returncode != 0:
            return Outcome(script.label, "fail", "-Wno-error=%s: smachac exited %d"
                           % (kind, returncode), time.monotonic() - began, stderr)
        finished = run_program(self.core, program, RUN_TIMEOUT)
        result, _ = final_outcome(finished)
        seconds = time.monotonic() - began
        refused = result is not None and result["outcome"] is None  # execute() returned None
        if not refused or error not in finished.stdout + finished.stderr:
            return Outcome(script.label, "fail", "compiled with -Wno-error=%s, SMACH did not "
                           "refuse it with %s" % (kind, error), seconds,
                           finished.stdout + finished.stderr)
        return Outcome(script.label, "ok", "rejected [%s] (%s); compiled with -Wno-error, "
                       "SMACH refuses it too (%s, no outcome)" % (kind, why, error), seconds)

    def run(self, script, program, began):
        expected = EXPECTED.get(script.key)
        with corpus_bags.Bags(script.text) as bags:
            if needs_master(program):
                case_dir = os.path.join(self.work_dir, script.key.replace("/", "__"))
                os.makedirs(case_dir)
                finished = run_with_master(self.overlay, case_dir, program,
                                           python_path=[self.messages], timeout=RUN_TIMEOUT)
            else:
                finished = run_program(self.core, program, RUN_TIMEOUT)
            problem = bags.problem()
        seconds = time.monotonic() - began
        result, why = final_outcome(finished)
        if why:
            why, _, details = why.partition("\n")
            return Outcome(script.label, "fail", why, seconds, details)
        self.reached[script.key] = result["outcome"]
        if result["outcome"] != expected:
            return Outcome(script.label, "fail", "outcome %s, expected %s"
                           % (result["outcome"], expected or "none: add it to "
                              "smacha_corpus_expected.py"), seconds, finished.stderr)
        if problem:
            return Outcome(script.label, "fail", problem, seconds)
        return Outcome(script.label, "ok", "outcome %s%s" % (expected, bags.summary()), seconds)


def sub_script_line(sub, scripts, outcomes):
    """A sub-script is no program of its own (it has no base template): its line says which
    scripts include it, and it passes when they compiled and ran."""
    parents = [s for s in scripts if s is not sub and s.includes(sub)]
    bad = [p.name for p in parents if outcomes[p.label].kind != "ok"]
    if bad:
        return Outcome(sub.label, "fail", "sub-script of %s, which failed" % ", ".join(bad))
    return Outcome(sub.label, "ok", "sub-script of %s" % ", ".join(p.name for p in parents))


class Collector:
    """Keeps each Outcome instead of printing it (sub-scripts are reported after the rest)."""

    def __init__(self):
        self.outcomes = {}

    def ok(self, label, text, seconds=None):
        self.outcomes[label] = Outcome(label, "ok", text, seconds)

    def fail(self, label, text, seconds=None, details=""):
        self.outcomes[label] = Outcome(label, "fail", text, seconds, details)

    def skip(self, label, text):
        self.outcomes[label] = Outcome(label, "skip", text)


def measure(scripts, runner):
    """The closing summary: how many programs compiled, ran, and to which outcomes."""
    programs = [s for s in scripts if not s.sub_script]
    compiled = [s for s in programs if s.key in runner.compiled]
    reached = {}
    for key, outcome in runner.reached.items():
        reached[outcome] = reached.get(outcome, 0) + 1
    return "\n".join(
        ["corpus: %d scripts (and %d sub-scripts): %d compiled, %d rejected as expected, %d ran "
         "to a final outcome" % (len(programs), len(scripts) - len(programs), len(compiled),
                                 sum(1 for s in programs if s.key in REJECTED),
                                 len(runner.reached))] +
        ["corpus: outcome %s reached by %d" % (outcome, reached[outcome])
         for outcome in sorted(reached)])


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    smachac = os.path.abspath(sys.argv[1])
    if len(sys.argv) == 3:
        smacha_dir = os.path.abspath(sys.argv[2])
    else:
        found = frameworks.find_checkout("smacha")
        if isinstance(found, frameworks.Missing):
            print("skip smacha-corpus (%s)" % unavailable([found]))
            return SKIPPED
        smacha_dir = found.path
    scripts = corpus(smacha_dir)
    if not scripts:
        print("skip smacha-corpus (no SMACHA test scripts under %s)" % smacha_dir)
        return SKIPPED
    overlay = os.environ.get("SMACHAC_ROS_OVERLAY", "")

    def body(core, work_dir):
        collector = Collector()
        runner = Corpus(smachac, smacha_dir, overlay, core, work_dir)
        run_in_order(scripts, runner.check, collector, lambda s: s.label)
        report = Report()
        for script in scripts:
            outcome = collector.outcomes[script.label]
            if script.sub_script:
                outcome = sub_script_line(script, scripts, collector.outcomes)
            outcome.report_to(report)
        print(measure(scripts, runner))
        return report.close()

    return run_test("smacha-corpus", ["smach"], body, master=False)


if __name__ == "__main__":
    sys.exit(main())
