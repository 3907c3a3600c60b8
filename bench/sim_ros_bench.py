#!/usr/bin/python3
"""Real-time factor of the paper's three experiments as SMACH Python and as FlexBE behaviors on
the simulated Baxter over ROS (tools/baxter-ros-run), beside which the C++ programs'
(sim_experiments_bench.py) compare.

usage: sim_ros_bench.py [RESULTS_DIR [BUILD_DIR]]
The build tree is BUILD_DIR, else $SMACHAC_BENCH_BUILD (bench/run.sh sets it), else build-bench;
the ROS overlay is its own, else the test tree's (build/ros-overlay, which `make test` builds).
Each experiment runs three times per target; the best run by wall time is shown: the simulated
time of the machine's run, the node's wall time over it, and their ratio. Every run must end
`outcome: succeeded`; where ROS or a framework is not available the target is skipped, saying
why.
"""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXPERIMENTS = ("pick_and_place", "stacking", "dual_arm_stacking")
SKIPPED = 77


class Skip(Exception):
    pass


def overlay_of(build):
    for tree in (build, ROOT / "build"):
        if (tree / "ros-overlay" / "overlay.json").exists():
            return ["--overlay", str(tree / "ros-overlay")]
    return []


def run_once(build, target, experiment):
    """(simulated seconds, wall seconds) of one run, from the node's report."""
    with tempfile.TemporaryDirectory() as work:
        report = os.path.join(work, "report.json")
        result = subprocess.run(
            [sys.executable, str(ROOT / "tools" / "baxter-ros-run"), "--target", target,
             "--build", str(build), "--report-json", report, *overlay_of(build),
             str(ROOT / "examples" / "baxter" / (experiment + ".yml"))],
            capture_output=True, text=True, timeout=900)
        if result.returncode == SKIPPED:
            raise Skip(result.stdout.strip().splitlines()[-1])
        if result.returncode != 0 or "outcome: succeeded" not in result.stdout:
            sys.exit(f"sim_ros_bench: {target} {experiment} failed:\n{result.stdout[-2000:]}"
                     f"{result.stderr[-2000:]}")
        with open(report, encoding="utf-8") as f:
            description = json.load(f)
        return description["simulated"], description["wall_seconds"]


def main():
    build = Path(sys.argv[2] if len(sys.argv) > 2 else
                 os.environ.get("SMACHAC_BENCH_BUILD", ROOT / "build-bench")).resolve()
    for target in ("smach", "flexbe"):
        try:
            for experiment in EXPERIMENTS:
                simulated, wall = min((run_once(build, target, experiment) for _ in range(3)),
                                      key=lambda r: r[1])
                print(f"sim-ros/{target}/{experiment:<18} {simulated:6.2f} s simulated in "
                      f"{wall:5.2f} s wall: real-time factor {simulated / wall:5.1f}")
        except Skip as why:
            print(f"sim-ros/{target}: skipped ({why})")


if __name__ == "__main__":
    main()
