#!/usr/bin/env bash
# `make demo`: compiles every example script, then prints the IR of one of them.
set -euo pipefail
smachac=${1:?usage: tools/demo.sh path/to/smachac}
cd "$(dirname "$0")/.."
echo "== smachac lint: every example"
mapfile -t scripts < <(find examples -name '*.yml' -not -path '*/sub/*' | sort)
"$smachac" lint -S examples/core/sub "${scripts[@]}"
echo "   ${#scripts[@]} scripts, no diagnostics"
echo
echo "== smachac -target=ir examples/core/sub_scripts.yml"
"$smachac" -target=ir examples/core/sub_scripts.yml
