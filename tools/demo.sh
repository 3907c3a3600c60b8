#!/usr/bin/env bash
# `make demo`: checks every example script, prints the IR of one, and compiles one to SMACH
# Python (checked with py_compile) under build/demo/.
set -euo pipefail
smachac=${1:?usage: tools/demo.sh path/to/smachac}
cd "$(dirname "$0")/.."
echo "== smachac lint: every example"
"$smachac" lint examples/core/*.yml
# The Baxter scripts' templates exist for the simulation's C++ states, not yet as template
# sets: check their structure, data flow and names (-target=ir) without template checks.
"$smachac" lint -target=ir examples/baxter/*.yml
echo "   $(ls examples/core/*.yml examples/baxter/*.yml | wc -l) scripts, no diagnostics"
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
