#!/usr/bin/env bash
# `make demo-ros`: the paper's stacking experiment as the paper ran it, through SMACH Python on
# a simulated Baxter over ROS: examples/baxter/stacking.yml compiled by smachac with the Baxter
# SMACH templates, run unchanged by tools/baxter-ros-run on a private ROS master with the
# MuJoCo Baxter node (sim/ros). Writes into <build-dir>/demo-ros/:
#   NNN_<gripper action>.png   snapshots (after each gripper action, at the end)
#   run.log                    the trace, the outcome and the scene report
# Exits 0 only when the machine succeeded and the report says the blocks are stacked.
#
#   sim/ros/run_demo_ros.sh <build-dir>
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 <build-dir>" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
demo="$build/demo-ros"
mkdir -p "$demo"
rm -f "$demo"/*.png

echo "== running examples/baxter/stacking.yml as SMACH Python on the simulated Baxter over ROS"
status=0
/usr/bin/python3 "$root/tools/baxter-ros-run" --build "$build" --snapshots "$demo" \
  "$root/examples/baxter/stacking.yml" 2>&1 | tee "$demo/run.log" || status=$?

bash "$root/sim/experiments/demo_verdict.sh" "$demo" "$status"
