#!/usr/bin/env bash
# The end of both demos (run_demo.sh, sim/ros/run_demo_ros.sh): lists the snapshots of
# <demo-dir> and judges <demo-dir>/run.log, the output of a Baxter program that exited with
# <status>. Exits 0 only when the program exited 0, its machine succeeded and the scene report
# says the blocks are stacked.
#
#   sim/experiments/demo_verdict.sh <demo-dir> <status>
set -euo pipefail

demo=${1:?usage: demo_verdict.sh <demo-dir> <status>}
status=${2:?usage: demo_verdict.sh <demo-dir> <status>}

echo "== snapshots"
ls "$demo"/*.png 2>/dev/null || echo "(none)"

echo "== verdict"
if [[ $status -ne 0 ]]; then
  echo "FAILED: the program exited with $status"
  exit 1
fi
if ! grep -q '^outcome: succeeded$' "$demo/run.log"; then
  echo "FAILED: $(grep '^outcome:' "$demo/run.log" || echo 'no outcome')"
  exit 1
fi
if ! grep -q '^  stacked: ' "$demo/run.log"; then
  echo "FAILED: $(grep 'stacked' "$demo/run.log" || echo 'no stack verdict')"
  exit 1
fi
echo "SUCCESS: outcome succeeded,$(grep '^  stacked: ' "$demo/run.log" | sed 's/^ *//;s/^/ /')"
