#!/usr/bin/python3
"""Reproduces Table I of the SMACHA paper for smachac's Baxter experiments.

For each experiment (examples/baxter: pick_and_place, stacking, dual_arm_stacking, in the
paper's order) it counts files/lines (lines as `wc -l` counts them) of:

  templates    the Baxter templates the experiment uses that no earlier experiment used:
               the templates its script and sub-scripts name (`template:`) that are files of
               the target's Baxter template folder (sim/templates/<target>), plus the files
               of that folder they extend, import or include, transitively. The core
               templates built into smachac (Base, State, StateMachine, Concurrence, Utils)
               are not counted, as the paper did not count SMACHA's core templates.
  sub-scripts  the sub-scripts (`script:`, transitively) that no earlier experiment used;
  scripts      the experiment's own script;
  total        the sum of the three;
  generated    what `smachac -target=<target>` writes for the script (one file for smach
               and cpp; for flexbe, with -flexbe-ros=1, the behavior module, the states
               module and the manifest).

So, as in the paper, the templates and sub-scripts are counted once, for the first
experiment that uses them; a later experiment counts only what it adds. Each cell is
printed as `ours (paper)`; the paper's figures are for SMACH Python on Gazebo.

After each table comes how the experiments run on the simulated Baxter (MuJoCo): the C++
programs of sim/experiments directly, the SMACH and FlexBE programs over ROS through
tools/baxter-ros-run. With --run each experiment is executed and its outcome, verdict and
simulated time are printed; without it, the ctest that executes it is named.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXPERIMENTS = [("Pick & Place", "pick_and_place"), ("Stacking", "stacking"),
               ("Dual-Arm", "dual_arm_stacking")]
COLUMNS = ["templates", "sub-scripts", "scripts", "total", "generated"]
PAPER = {  # Table I of the paper, files/lines per column
    "Pick & Place": [(5, 466), (2, 66), (1, 45), (8, 577), (1, 372)],
    "Stacking": [(0, 0), (0, 0), (1, 71), (1, 71), (1, 478)],
    "Dual-Arm": [(0, 0), (0, 0), (1, 102), (1, 102), (1, 513)],
}
TEMPLATE_SUFFIX = {"smach": ".tpl.py", "flexbe": ".tpl.py", "cpp": ".tpl.cpp"}
TARGET_ARGS = {"smach": [], "cpp": [], "flexbe": ["-flexbe-ros=1"]}
REFERENCE = re.compile(r"{%-?\s*(?:extends|include|import|from)\s+[\"']([^\"']+)[\"']")


def line_count(path):
    with open(path, "rb") as f:
        return f.read().count(b"\n")


def script_references(path):
    """(template names, sub-script names) a script names directly."""
    with open(path, encoding="utf-8") as f:
        data = yaml.safe_load(f)
    templates, scripts = set(), set()
    stack = [data]
    while stack:
        node = stack.pop()
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "template" and isinstance(value, str):
                    templates.add(value)
                elif key == "script" and isinstance(value, str):
                    scripts.add(value)
                else:
                    stack.append(value)
        elif isinstance(node, list):
            stack.extend(node)
    return templates, scripts


def scripts_used(script, script_dir):
    """The sub-script files a script uses, transitively, and every template name named."""
    templates, sub_scripts, pending = set(), [], [script]
    while pending:
        names, subs = script_references(pending.pop())
        templates |= names
        for sub in sorted(subs):
            path = os.path.join(script_dir, sub + ".yml")
            if path not in sub_scripts:
                sub_scripts.append(path)
                pending.append(path)
    return templates, sub_scripts


def template_files(names, template_dir, suffix):
    """The files of template_dir that the named templates are or reference, transitively."""
    found, pending = set(), [name + suffix for name in names]
    while pending:
        path = os.path.join(template_dir, pending.pop())
        if path in found or not os.path.isfile(path):
            continue  # a core template, built into smachac
        found.add(path)
        with open(path, encoding="utf-8") as f:
            pending += REFERENCE.findall(f.read())
    return found


def generated_files(smachac, target, template_dir, script_dir, script):
    """(files, lines) of what smachac writes for the script."""
    command = [smachac, "-target=" + target] + TARGET_ARGS[target] + [
        "-I", template_dir, "-S", script_dir, script]
    with tempfile.TemporaryDirectory() as out:
        if target == "flexbe":
            command += ["-o", out]
        else:
            command += ["-o", os.path.join(out, "generated")]
        result = subprocess.run(command, capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit(f"table1: `{' '.join(command)}` failed:\n{result.stderr}")
        files = [os.path.join(out, f) for f in sorted(os.listdir(out))]
        return len(files), sum(line_count(f) for f in files)


def measure(target, smachac, root):
    """Rows [(experiment, [(files, lines)] per column, counted file names)]."""
    template_dir = os.path.join(root, "sim", "templates", target)
    script_dir = os.path.join(root, "examples", "baxter")
    seen_templates, seen_scripts, rows = set(), set(), []
    for label, stem in EXPERIMENTS:
        script = os.path.join(script_dir, stem + ".yml")
        names, sub_scripts = scripts_used(script, script_dir)
        templates = template_files(names, template_dir, TEMPLATE_SUFFIX[target]) - seen_templates
        new_scripts = [s for s in sub_scripts if s not in seen_scripts]
        seen_templates |= templates
        seen_scripts |= set(new_scripts)
        cells = [(len(group), sum(line_count(f) for f in group))
                 for group in (sorted(templates), new_scripts, [script])]
        cells.append((sum(c[0] for c in cells), sum(c[1] for c in cells)))
        cells.append(generated_files(smachac, target, template_dir, script_dir, script))
        counted = [os.path.basename(f) for f in sorted(templates)]
        counted += [os.path.relpath(f, script_dir) for f in new_scripts]
        rows.append((label, cells, counted))
    return rows


def print_table(target, rows):
    print(f"Table I, target {target} (files/lines; ours (paper)); templates from "
          f"sim/templates/{target}, scripts from examples/baxter")
    print()
    print("| experiment | " + " | ".join(COLUMNS) + " |")
    print("|---" * (len(COLUMNS) + 1) + "|")
    for label, cells, _ in rows:
        shown = [f"{f}/{l} ({pf}/{pl})" for (f, l), (pf, pl) in zip(cells, PAPER[label])]
        print(f"| {label} | " + " | ".join(shown) + " |")
    print()
    for label, _, counted in rows:
        print(f"{label} counts: " + (", ".join(counted) if counted else
                                     "no template or sub-script not counted above"))


RUN_TESTS = {"cpp": "ctest -R sim_generated_{stem}", "smach": "ctest -R sim-ros/smach-{stem}",
             "flexbe": "ctest -R sim-ros/flexbe-{stem}"}
REPORT_LINE = re.compile(r"^  ((?:not )?stacked: .*|block1 at .*)$", re.MULTILINE)


def run_command(target, stem, root, build):
    script = os.path.join(root, "examples", "baxter", stem + ".yml")
    if target == "cpp":
        return [os.path.join(build, "sim", "experiments", "baxter_" + stem), "--robot-quiet"]
    return [sys.executable, os.path.join(root, "tools", "baxter-ros-run"), "--target", target,
            "--build", build, script]


def run_experiment(target, stem, root, build):
    """`outcome; verdict (or block1's place); simulated time` of one run on the simulated
    Baxter, or why it did not run."""
    try:
        result = subprocess.run(run_command(target, stem, root, build), capture_output=True,
                                text=True, timeout=600)
    except (OSError, subprocess.TimeoutExpired) as error:
        return f"not run: {error}"
    outcome = re.search(r"^outcome: (\S+)$", result.stdout, re.MULTILINE)
    if outcome is None:
        last = (result.stdout + result.stderr).strip().splitlines()
        return f"not run: {last[-1] if last else 'exit %d' % result.returncode}"
    verdicts = REPORT_LINE.findall(result.stdout)
    verdict = verdicts[-1] if stem != "pick_and_place" else verdicts[0]
    simulated = re.search(r"^scene after ([0-9.]+ s) simulated", result.stdout, re.MULTILINE)
    return "; ".join([outcome.group(1), verdict] + ([simulated.group(1) + " simulated"]
                                                    if simulated else []))


def print_runs(target, root, build):
    how = ("its C++ program (sim/experiments)" if target == "cpp" else
           "tools/baxter-ros-run, over ROS")
    print()
    print(f"On the simulated Baxter, target {target}, through {how}:")
    for label, stem in EXPERIMENTS:
        if build:
            print(f"  {label}: {run_experiment(target, stem, root, build)}")
        else:
            print(f"  {label}: executed by `{RUN_TESTS[target].format(stem=stem)}` "
                  "(--run executes it here)")


def find_smachac(root):
    path = os.path.join(root, "build", "tools", "smachac", "smachac")
    if not os.access(path, os.X_OK):
        sys.exit("table1: no smachac binary in build/ (run `make build` or pass --smachac)")
    return path


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--target", choices=["smach", "cpp", "flexbe", "all"], default="all",
                        help="the target whose Baxter templates and output are counted "
                             "(default all)")
    parser.add_argument("--smachac", help="the smachac binary (default build/tools/smachac/"
                                          "smachac)")
    parser.add_argument("--run", action="store_true",
                        help="execute each experiment on the simulated Baxter")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"),
                        help="the build tree whose programs --run executes (default build/)")
    parser.add_argument("--root", default=ROOT, help=argparse.SUPPRESS)
    args = parser.parse_args()
    smachac = os.path.abspath(args.smachac) if args.smachac else find_smachac(args.root)
    if not os.access(smachac, os.X_OK):
        sys.exit(f"table1: {smachac} is not an executable smachac")
    targets = ["smach", "cpp", "flexbe"] if args.target == "all" else [args.target]
    for i, target in enumerate(targets):
        if i:
            print()
        print_table(target, measure(target, smachac, args.root))
        print_runs(target, args.root, os.path.abspath(args.build) if args.run else None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
