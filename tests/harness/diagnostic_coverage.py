#!/usr/bin/env python3
"""Fails when a diagnostic kind of ir/support/diagnostic_kinds.def has no golden test.

A kind is covered when `[kind-name]` appears in some tests/golden/**/*.stderr file (text
diagnostics end with the kind in brackets) or in an assertion of tests/e2e/*.py."""
import glob
import os
import re
import sys


def main():
    root = sys.argv[1]
    with open(os.path.join(root, "ir/support/diagnostic_kinds.def"), encoding="utf-8") as f:
        kinds = re.findall(r'^SMACHAC_DIAGNOSTIC\(\s*\w+,\s*"([a-z0-9-]+)"', f.read(), re.M)
    seen = set()
    for path in glob.glob(os.path.join(root, "tests/golden/**/*.stderr"), recursive=True):
        with open(path, encoding="utf-8", errors="replace") as f:
            seen.update(re.findall(r"\[([a-z0-9-]+)\]$", f.read(), re.M))
    # End-to-end tests cover the kinds whose inputs cannot be committed (a 33 MB script, a
    # chain of 70 sub-scripts): they assert the full diagnostic line, kind included.
    for path in glob.glob(os.path.join(root, "tests/e2e/*.py")):
        with open(path, encoding="utf-8") as f:
            seen.update(re.findall(r"\[([a-z0-9-]+)\]", f.read()))
    missing = [k for k in kinds if k not in seen]
    for k in missing:
        print(f"diagnostic kind `{k}` has no golden test (no tests/golden/**/*.stderr names it)")
    print(f"{len(kinds) - len(missing)} of {len(kinds)} diagnostic kinds covered")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
