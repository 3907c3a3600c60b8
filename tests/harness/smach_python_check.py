#!/usr/bin/env python3
"""Checks the expected SMACH Python of the golden cases (tests/golden/<area>/*.smach.py).

  smach_python_check.py compile DIR...   every expected file must byte-compile (py_compile)
  smach_python_check.py execute DIR...   run each file's main() and check the outcome of the
                                         top state machine; exits 77 (skipped) when `import
                                         smach` fails, e.g. on Debian, which does not package it

A case's leading comments may hold `# OUTCOME: <outcome>` (the expected outcome; otherwise
any outcome will do) or `# EXECUTE: no (<why>)` (the case is not meant to run). Files that
import rospy run only where rospy imports. `random` is seeded, so outcomes are repeatable.
"""
import glob
import os
import py_compile
import subprocess
import sys
import tempfile

SKIPPED = 77

RUNNER = r'''
import random, runpy, sys
import smach
random.seed(0)
outcomes, depth = [], [0]
original = smach.StateMachine.execute
def execute(self, *args, **kwargs):
    depth[0] += 1
    try:
        result = original(self, *args, **kwargs)
    finally:
        depth[0] -= 1
    if depth[0] == 0:
        outcomes.append(result)
    return result
smach.StateMachine.execute = execute
runpy.run_path(sys.argv[1], run_name='__main__')
print('OUTCOME=%s' % (outcomes[-1] if outcomes else None))
'''


def expected_files(dirs):
    files = []
    for d in dirs:
        files += sorted(glob.glob(os.path.join(d, "*.smach.py")))
    return files


def header(py_file):
    """(expected outcome or None, reason not to run or None) from the case's comments."""
    case = py_file[:-len(".smach.py")] + ".yml"
    outcome, skip = None, None
    with open(case, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith("# OUTCOME:"):
                outcome = line.split(":", 1)[1].strip()
            if line.startswith("# EXECUTE: no"):
                skip = line.split("no", 1)[1].strip(" ()\n") or "marked not to run"
    return outcome, skip


def check_compile(files):
    failed = 0
    with tempfile.TemporaryDirectory() as scratch:
        for path in files:
            try:
                cfile = os.path.join(scratch, os.path.basename(path) + "c")
                py_compile.compile(path, cfile=cfile, doraise=True)
            except py_compile.PyCompileError as e:
                print(f"FAIL {path}: {e.msg}")
                failed += 1
    print(f"{len(files) - failed} of {len(files)} expected SMACH files compile")
    return 1 if failed else 0


def importable(module):
    return subprocess.run([sys.executable, "-c", f"import {module}"],
                          capture_output=True).returncode == 0


def run_one(path, expected):
    result = subprocess.run([sys.executable, "-c", RUNNER, path], capture_output=True,
                            text=True, timeout=60, cwd=os.path.dirname(path))
    lines = [l for l in result.stdout.splitlines() if l.startswith("OUTCOME=")]
    if result.returncode != 0 or not lines:
        return f"exit {result.returncode}: {result.stderr.strip()[-400:]}"
    actual = lines[-1][len("OUTCOME="):]
    if expected is not None and actual != expected:
        return f"outcome {actual}, expected {expected}"
    return None


def check_execute(files):
    if not importable("smach"):
        print("skipped: `import smach` fails (SMACH is not installed; Debian does not package "
              "it), so the expected files cannot run here")
        return SKIPPED
    has_ros = importable("rospy")
    failed = ran = 0
    for path in files:
        expected, skip = header(path)
        with open(path, encoding="utf-8") as f:
            needs_ros = "import rospy" in f.read()
        if skip or (needs_ros and not has_ros):
            print(f"skip {os.path.basename(path)}: {skip or 'needs rospy'}")
            continue
        ran += 1
        problem = run_one(path, expected)
        if problem:
            print(f"FAIL {path}: {problem}")
            failed += 1
    print(f"{ran - failed} of {ran} expected SMACH files ran as expected")
    return 1 if failed else 0


def main():
    mode, dirs = sys.argv[1], sys.argv[2:]
    files = [os.path.abspath(f) for f in expected_files(dirs)]
    if not files:
        print("no expected SMACH files found")
        return 1
    return check_compile(files) if mode == "compile" else check_execute(files)


if __name__ == "__main__":
    sys.exit(main())
