#!/usr/bin/env python3
"""Checks that the expected SMACH Python of the golden cases (tests/golden/<area>/*.smach.py)
byte-compiles (py_compile).

  smach_python_check.py compile DIR...

tests/ros/smach_goldens.py executes them on the real SMACH (ctest ros/smach-goldens).
"""
import glob
import os
import py_compile
import sys
import tempfile


def expected_files(dirs):
    files = []
    for d in dirs:
        files += sorted(glob.glob(os.path.join(d, "*.smach.py")))
    return files


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


def main():
    if len(sys.argv) < 3 or sys.argv[1] != "compile":
        print(__doc__.strip(), file=sys.stderr)
        return 2
    files = [os.path.abspath(f) for f in expected_files(sys.argv[2:])]
    if not files:
        print("no expected SMACH files found")
        return 1
    return check_compile(files)


if __name__ == "__main__":
    sys.exit(main())
