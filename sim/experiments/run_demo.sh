#!/usr/bin/env bash
# The dual-arm stacking demo: runs the program smachac generated from
# examples/baxter/dual_arm_stacking.yml (target baxter_dual_arm_stacking) with the trace
# streaming, PNG snapshots and the final scene report, then draws the state machine.
#
#   sim/experiments/run_demo.sh <build-dir>
#
# Needs `cmake --build <build-dir> --target baxter_dual_arm_stacking smachac` first, and
# Graphviz's `dot`. Writes into <build-dir>/demo/:
#   NNN_<state path>.png       snapshots (after each gripper action, at the end)
#   run.log                    the trace, the outcome and the scene report
#   dual_arm_stacking.svg      the state machine (smachac -target=dot | dot -Tsvg)
# Exits 0 only when the machine succeeded and the report says the blocks are stacked.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 <build-dir>" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
program="$build/sim/experiments/baxter_dual_arm_stacking"
smachac="$build/tools/smachac/smachac"
script="$root/examples/baxter/dual_arm_stacking.yml"
demo="$build/demo"

for file in "$program" "$smachac"; do
  if [[ ! -x "$file" ]]; then
    echo "$0: $file is missing; build the targets baxter_dual_arm_stacking and smachac" >&2
    exit 2
  fi
done
mkdir -p "$demo"
rm -f "$demo"/*.png

echo "== the state machine: $demo/dual_arm_stacking.svg"
"$smachac" -target=dot -S "$root/examples/baxter" "$script" | dot -Tsvg -o "$demo/dual_arm_stacking.svg"

echo "== running $program (trace, snapshots in $demo)"
status=0
# The trace (stderr) streams as the machine runs; the outcome and the report go to stdout.
"$program" --trace=log --snapshots="$demo" --robot-quiet 2>&1 | tee "$demo/run.log" || status=$?

bash "$root/sim/experiments/demo_verdict.sh" "$demo" "$status"
