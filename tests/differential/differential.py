#!/usr/bin/python3
"""Differential execution: one script, every target, each on its real runtime, compared.

  differential.py SMACHAC CXX RUNTIME_LIB RUNTIME_INCLUDE [CASE...]

(CASE: run only the cases whose name contains one of these texts.)

Each case is compiled for smach, cpp and flexbe (ROS 1), run on the real SMACH, the C++
runtime and the real flexbe_core, and what happened is compared with the SMACH run: the
states entered in order with each outcome (canonical.py), the final outcome and the final
userdata. Cases:
  * tests/differential/cases/*.yml: written for this test. `# TARGETS: smach cpp` limits the
    targets; `<case>.<target>.yml` beside a case replaces it for that target (an equivalent
    script, e.g. where a callback is target code); `# EXPECT: <outcome>` is the final outcome
    every target must reach; `# PREEMPT-AFTER: <seconds>` preempts the machine that long
    after it starts, the way each target is preempted (targets.py).
  * examples/core/*.yml, and the golden scripts of tests/golden/{smach,flexbe} that take no
    template folder: compared on the targets that compile them (the others are listed with
    the reason). A script that draws a random outcome among several is compared once per
    combination of outcomes, each random state pinned to one (pinning.py): Python's and the
    C++ runtime's generators draw differently.
A difference fails the test, unless KNOWN_DIFFERENCES names the case and the target with the
rule that explains it; such a case must then differ exactly as recorded, so the rule stays
demonstrated. Prints one line per case and target, then `N passed, N failed, N skipped`.
"""
import concurrent.futures
import glob
import os
import shlex
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path[:0] = [os.path.join(ROOT, "tests", "ros"), os.path.join(ROOT, "tools", "ros")]

import canonical  # noqa: E402
import known_differences  # noqa: E402
import pinning  # noqa: E402
import targets  # noqa: E402
from report import Report  # noqa: E402
from ros_session import run_test  # noqa: E402

ALL_TARGETS = ("smach", "cpp", "flexbe")


class Case:
    def __init__(self, name, script, written_for_test):
        self.name = name
        self.script = script
        self.written_for_test = written_for_test
        self.header = header(script)

    def targets(self):
        listed = self.header.get("TARGETS")
        return tuple(listed.split()) if listed else ALL_TARGETS

    def preempt_after(self):
        seconds = self.header.get("PREEMPT-AFTER")
        return float(seconds) if seconds else None

    def script_for(self, target):
        variant = self.script[:-len(".yml")] + "." + target + ".yml"
        return variant if os.path.exists(variant) else self.script


def header(path):
    fields = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, _, value = line[1:].strip().partition(":")
            if key.replace("-", "").isupper():
                fields[key] = value.strip()
    return fields


def takes_template_folder(path):
    args = shlex.split(header(path).get("ARGS", ""))
    return any(a.startswith("-I") or a.startswith("-S") or a.startswith("%") for a in args)


def uses_ros(path):
    """ROS scripts run against their servers in ros/smach-goldens; no other target has them."""
    with open(path, encoding="utf-8") as f:
        return "template: ROSBase" in f.read()


def discover():
    cases = []
    for path in sorted(glob.glob(os.path.join(HERE, "cases", "*.yml"))):
        stem = os.path.basename(path)[:-len(".yml")]
        if "." not in stem:  # `<case>.<target>.yml` are variants, not cases
            cases.append(Case("cases/" + stem, path, True))
    for path in sorted(glob.glob(os.path.join(ROOT, "examples", "core", "*.yml"))):
        cases.append(Case("examples/" + os.path.basename(path)[:-4], path, False))
    for area in ("smach", "flexbe"):
        for path in sorted(glob.glob(os.path.join(ROOT, "tests", "golden", area, "*.yml"))):
            name = os.path.basename(path)[:-4]
            if name.startswith("fail_") or takes_template_folder(path) or uses_ros(path):
                continue
            if "EXECUTE" in header(path) and header(path)["EXECUTE"].startswith("no"):
                continue
            cases.append(Case("golden/%s/%s" % (area, name), path, False))
    return cases


def describe(run, concurrences):
    return {"lines": canonical.lines(run.events, concurrences),
            "outcome": run.result["outcome"], "userdata": run.result["userdata"]}


def differences(reference, other):
    found = []
    if reference["lines"] != other["lines"]:
        found.append("states: smach %s, this %s" % (reference["lines"], other["lines"]))
    if reference["outcome"] != other["outcome"]:
        found.append("outcome: smach %s, this %s" % (reference["outcome"], other["outcome"]))
    if canonical.typed(reference["userdata"]) != canonical.typed(other["userdata"]):
        found.append("userdata: smach %s, this %s" % (reference["userdata"], other["userdata"]))
    return found


def run_case(tools, case):
    """{target: Run} for every target of the case (C++ builds run in parallel elsewhere)."""
    return {t: targets.RUNNERS[t](tools, case.name.replace("/", "__"), case.script_for(t),
                                  case.preempt_after())
            for t in case.targets()}


def judge(report, tools, case, runs):
    ir = tools.ir_json(case.script)
    concurrences = canonical.concurrence_paths(ir) if ir else set()
    if ir and canonical.random_choices(ir):
        return report.skip(case.name, "draws a random outcome in %s and cannot be pinned: in "
                           "a loop, in a sub-script or with target variants (pinning.py)"
                           % sorted(canonical.random_choices(ir)))
    reference = runs.get("smach")
    if reference is None or reference.problem:
        why = reference.problem if reference else "not a smach case"
        verdict = report.fail if case.written_for_test else report.skip
        return verdict(case.name, "smach: " + why)
    ref = describe(reference, concurrences)
    expected = case.header.get("EXPECT")
    if expected and ref["outcome"] != expected:
        return report.fail(case.name, "smach ends %s, expected %s" % (ref["outcome"], expected))
    for target, run in runs.items():
        if target != "smach":
            judge_target(report, case, target, run, ref, concurrences)


def judge_target(report, case, target, run, ref, concurrences):
    label = "%s [%s]" % (case.name, target)
    if run.problem:
        compile_only = run.problem.startswith("smachac: ") and not case.written_for_test
        return (report.skip if compile_only else report.fail)(label, run.problem)
    found = differences(ref, describe(run, concurrences))
    known = known_differences.RULES.get((case.name, target))
    if known is None:
        detail = "same as smach (%d states, outcome %s)" % (len(ref["lines"]), ref["outcome"])
        return report.fail(label, "; ".join(found)) if found else report.ok(label, detail)
    if found == known.expected(ref):
        return report.ok(label, "differs as known: " + known.rule)
    report.fail(label, "known difference (%s) not as recorded: %s" %
                (known.rule, "; ".join(found) or "no difference"))


def pin(tools, case, work_dir):
    """The case, or its variants with every random choice pinned (pinning.py)."""
    ir = tools.ir_json(case.script)
    choices = canonical.random_choices(ir) if ir else {}
    has_target_variants = any(case.script_for(t) != case.script for t in ALL_TARGETS)
    if not choices or has_target_variants or any(canonical.in_loop(ir, p) for p in choices):
        return [case]
    found = pinning.variants(case.name, case.script, choices, work_dir)
    if found is None:
        return [case]
    return [Case(name, script, case.written_for_test) for name, script in found]


def main():
    smachac, cxx, runtime_lib, runtime_include = [os.path.abspath(a) if os.path.exists(a) else a
                                                  for a in sys.argv[1:5]]
    only = sys.argv[5:]
    report = Report()

    def body(session, work):
        tools = targets.Toolchain(smachac, cxx, runtime_lib, runtime_include, session, work)
        cases = [c for c in discover() if not only or any(o in c.name for o in only)]
        cases = [pinned for c in cases for pinned in pin(tools, c, work)]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            results = list(pool.map(lambda c: run_case(tools, c), cases))
        for case, runs in zip(cases, results):
            judge(report, tools, case, runs)
        return report.close()

    return run_test("differential", ["smach", "flexbe"], body)


if __name__ == "__main__":
    sys.exit(main())
