#!/usr/bin/env bash
# Runs every benchmark of a build tree and prints a summary.
#   usage: bench/run.sh <build-dir>      (the tree must be configured with -DSMACHAC_BUILD_BENCH=ON)
# Every executable <build-dir>/bench/bench_* runs with its JSON results kept in a scratch
# directory; then every reference script bench/*.py runs with that directory as its argument
# (e.g. tmpl_bench_jinja.py times the same workload with python3-jinja2 and prints the ratio).
set -euo pipefail

build=${1:?usage: bench/run.sh <build-dir>}
here=$(cd "$(dirname "$0")" && pwd)
python=${SMACHAC_PYTHON:-/usr/bin/python3}
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

shopt -s nullglob
binaries=("$build"/bench/bench_*)
if [ ${#binaries[@]} -eq 0 ]; then
  echo "bench/run.sh: no bench_* executables in $build/bench (configure with -DSMACHAC_BUILD_BENCH=ON)" >&2
  exit 2
fi

for exe in "${binaries[@]}"; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  name=$(basename "$exe")
  echo "== $name"
  "$exe" --benchmark_out="$results/$name.json" --benchmark_out_format=json
  echo
done

summary=()
export SMACHAC_BENCH_BUILD="$build"   # reference scripts that run smachac find it here
for script in "$here"/*.py; do
  echo "== $(basename "$script")"
  while IFS= read -r line; do
    echo "$line"
    summary+=("$line")
  done < <("$python" "$script" "$results")
  echo
done

echo "== summary"
for exe in "${binaries[@]}"; do
  name=$(basename "$exe")
  "$python" - "$results/$name.json" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
for b in data["benchmarks"]:
    if "cpu_time" not in b or "time_unit" not in b:
        continue  # aggregates (BigO, RMS) have no time of their own
    print(f"{b['name']:<32} {b['cpu_time']:10.2f} {b['time_unit']} (cpu)")
PY
done
for line in "${summary[@]}"; do echo "$line"; done
