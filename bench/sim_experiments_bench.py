#!/usr/bin/python3
"""Real-time factor of the paper's three experiments as smachac generates them.

usage: sim_experiments_bench.py [RESULTS_DIR [BUILD_DIR]]
The build tree is BUILD_DIR, else $SMACHAC_BENCH_BUILD (bench/run.sh sets it), else build-bench;
it must hold sim/experiments/baxter_<experiment> (examples/baxter/<experiment>.yml compiled by
`smachac -target=cpp` with sim/templates/cpp). Each program runs headless (best of 3); the
simulated time is the one its scene report prints; the real-time factor is simulated seconds
per wall-clock second and per CPU second (the target is at least 15 on 2 cores). Every run
must end `outcome: succeeded`.
"""
import os
import re
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXPERIMENTS = ("pick_and_place", "stacking", "dual_arm_stacking")
SIMULATED = re.compile(r"scene after ([0-9.]+) s simulated")


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_once(program):
    """(simulated seconds, wall seconds, CPU seconds) of one run."""
    cpu_start, start = children_cpu(), time.perf_counter()
    result = subprocess.run([program, "--robot-quiet"], capture_output=True, text=True,
                            timeout=600)
    wall, cpu = time.perf_counter() - start, children_cpu() - cpu_start
    simulated = SIMULATED.search(result.stdout)
    if result.returncode != 0 or "outcome: succeeded" not in result.stdout or not simulated:
        sys.exit(f"sim_experiments_bench: {program} failed:\n{result.stdout[-2000:]}"
                 f"{result.stderr[-2000:]}")
    return float(simulated.group(1)), wall, cpu


def main():
    build = Path(sys.argv[2] if len(sys.argv) > 2 else
                 os.environ.get("SMACHAC_BENCH_BUILD", ROOT / "build-bench")).resolve()
    for experiment in EXPERIMENTS:
        program = build / "sim" / "experiments" / f"baxter_{experiment}"
        if not program.exists():
            sys.exit(f"sim_experiments_bench: build {program.name} in {build} first")
        simulated, wall, cpu = min((run_once(program) for _ in range(3)), key=lambda r: r[1])
        print(f"sim/{experiment:<18} {simulated:6.2f} s simulated in {wall:5.2f} s wall, "
              f"{cpu:5.2f} s cpu: real-time factor {simulated / wall:5.1f} wall, "
              f"{simulated / cpu:5.1f} cpu")


if __name__ == "__main__":
    main()
