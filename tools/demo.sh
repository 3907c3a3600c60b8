#!/usr/bin/env bash
# `make demo`, compiler part: checks every example script, prints the IR of one, and compiles
# one to SMACH Python (checked with py_compile) under build/demo/. The simulation part is
# sim/experiments/run_demo.sh.
set -euo pipefail
smachac=${1:?usage: tools/demo.sh path/to/smachac}
cd "$(dirname "$0")/.."
echo "== smachac lint: every example"
# The diagnostics are shown as lint prints them, then counted (a lint error stops the demo).
diagnostics=$(mktemp)
trap 'rm -f "$diagnostics"' EXIT
"$smachac" lint examples/core/*.yml 2> >(tee -a "$diagnostics" >&2)
# The Baxter scripts' templates are the simulation's C++ ones (sim/templates/cpp).
"$smachac" lint -target=cpp -I sim/templates/cpp examples/baxter/*.yml 2> >(tee -a "$diagnostics" >&2)
wait
warnings=$(grep -c ': warning: ' "$diagnostics" || true)
echo "   $(ls examples/core/*.yml examples/baxter/*.yml | wc -l) scripts, no errors, $warnings warning(s)"
echo
echo "== smachac -target=ir examples/core/sub_scripts.yml"
"$smachac" -target=ir examples/core/sub_scripts.yml
echo
mkdir -p build/demo
out=build/demo/nesting.py
echo "== smachac -target=smach examples/core/nesting.yml -o $out"
"$smachac" -target=smach examples/core/nesting.yml -o "$out"
/usr/bin/python3 -m py_compile "$out"
echo "   $(wc -l < "$out") lines of SMACH Python, compiled by python3 without errors:"
sed -n '/^def main/,$p' "$out"
