#!/usr/bin/env python3
"""Checks tools/table1.py (the paper's Table I for the Baxter experiments) against a count
made here independently, with `wc -l` and smachac run directly.

  table1_e2e.py <smachac>

For every target (smach, cpp, flexbe) the output must be the table in the paper's format
(header, the three experiments in order, each cell `ours (paper)`) with the paper's figures
as the paper reports them, and every one of our cells must equal the recount:
Pick & Place counts every template file of sim/templates/<target> except
FollowJointTrajActionState (no experiment uses it) and both sub-scripts; Stacking and
Dual-Arm count no template and no sub-script (they add none: Concurrence is a core
template); scripts are the experiment's file; generated is what smachac writes.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BAXTER = os.path.join(ROOT, "examples", "baxter")
EXPERIMENTS = [("Pick & Place", "pick_and_place"), ("Stacking", "stacking"),
               ("Dual-Arm", "dual_arm_stacking")]
PAPER = {"Pick & Place": "5/466 2/66 1/45 8/577 1/372",
         "Stacking": "0/0 0/0 1/71 1/71 1/478",
         "Dual-Arm": "0/0 0/0 1/102 1/102 1/513"}
HEADER = "| experiment | templates | sub-scripts | scripts | total | generated |"
CELL = re.compile(r"^(\d+)/(\d+) \((\d+/\d+)\)$")


def wc_lines(paths):
    """The total line count `wc -l` reports for the files."""
    if not paths:
        return 0
    out = subprocess.run(["wc", "-l"] + paths, capture_output=True, text=True,
                         check=True).stdout.split("\n")
    return int(out[-2].split()[0]) if len(paths) > 1 else int(out[0].split()[0])


def generated(smachac, target, script):
    templates = os.path.join(ROOT, "sim", "templates", target)
    with tempfile.TemporaryDirectory() as out:
        command = [smachac, "-target=" + target, "-I", templates, "-S", BAXTER, script]
        if target == "flexbe":
            command[2:2] = ["-flexbe-ros=1"]
            command += ["-o", out]
            subprocess.run(command, check=True)
            files = sorted(glob.glob(os.path.join(out, "*")))
            return len(files), wc_lines(files)
        path = os.path.join(out, "stdout")
        with open(path, "w") as f:
            subprocess.run(command, check=True, stdout=f)
        return 1, wc_lines([path])


def expected_rows(smachac, target):
    template_dir = os.path.join(ROOT, "sim", "templates", target)
    templates = [f for f in sorted(glob.glob(os.path.join(template_dir, "*.tpl.*")))
                 if not os.path.basename(f).startswith("FollowJointTrajActionState.")]
    subs = sorted(glob.glob(os.path.join(BAXTER, "sub", "*.yml")))
    rows = {}
    for i, (label, stem) in enumerate(EXPERIMENTS):
        script = os.path.join(BAXTER, stem + ".yml")
        t = (len(templates), wc_lines(templates)) if i == 0 else (0, 0)
        s = (len(subs), wc_lines(subs)) if i == 0 else (0, 0)
        own = (1, wc_lines([script]))
        total = (t[0] + s[0] + own[0], t[1] + s[1] + own[1])
        rows[label] = [t, s, own, total, generated(smachac, target, script)]
    return rows


def check_target(smachac, target, errors):
    result = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "table1.py"),
                             "--target", target, "--smachac", smachac],
                            capture_output=True, text=True)
    if result.returncode != 0:
        errors.append(f"{target}: table1.py exit {result.returncode}: {result.stderr}")
        return
    lines = result.stdout.splitlines()
    if not lines or not lines[0].startswith(f"Table I, target {target} "):
        errors.append(f"{target}: no title line: {lines[:1]}")
    if HEADER not in lines or lines[lines.index(HEADER) + 1] != "|---" * 6 + "|":
        errors.append(f"{target}: no table header")
        return
    rows = lines[lines.index(HEADER) + 2:lines.index(HEADER) + 5]
    expected = expected_rows(smachac, target)
    for (label, _), row in zip(EXPERIMENTS, rows):
        cells = [c.strip() for c in row.strip("|").split("|")]
        if cells[0] != label or len(cells) != 6:
            errors.append(f"{target}: row `{row}` is not {label}'s")
            continue
        for column, (cell, ours, paper) in enumerate(
                zip(cells[1:], expected[label], PAPER[label].split())):
            m = CELL.match(cell)
            if not m or (int(m.group(1)), int(m.group(2))) != ours or m.group(3) != paper:
                errors.append(f"{target}: {label} column {column + 1} is `{cell}`, expected "
                              f"`{ours[0]}/{ours[1]} ({paper})`")
    print(f"{target}: " + "; ".join(
        f"{label} " + " ".join(f"{f}/{l}" for f, l in expected[label])
        for label, _ in EXPERIMENTS))


def main():
    smachac = os.path.abspath(sys.argv[1])
    errors = []
    for target in ("smach", "cpp", "flexbe"):
        check_target(smachac, target, errors)
    for e in errors:
        print("FAIL " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
