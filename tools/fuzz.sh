#!/usr/bin/env bash
# Runs every libFuzzer harness of a build-fuzz tree for a set time, seeded from its committed
# corpus (tests/fuzz/corpus/<name>) and the golden scripts (the built-in templates for the
# template engine). New interesting inputs go to build-fuzz/corpus/<name>; crashes, leaks and
# inputs slower than 30 s to build-fuzz/artifacts/. Fails if any harness failed.
set -uo pipefail
build=${1:?usage: tools/fuzz.sh BUILD_DIR [SECONDS]}
seconds=${2:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
status=0
for fuzzer in "$build"/tests/fuzz/*; do
  [ -x "$fuzzer" ] && [ -f "$fuzzer" ] || continue
  name=$(basename "$fuzzer")
  case "$name" in *_replay) continue ;; esac
  corpus="$build/corpus/$name"
  artifacts="$build/artifacts"
  mkdir -p "$corpus" "$artifacts"
  seeds="$root/tests/golden"
  [ "$name" = tmpl ] && seeds="$root/templates"
  echo "== fuzz $name for ${seconds}s"
  "$fuzzer" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$name-" \
    "$corpus" "$root/tests/fuzz/corpus/$name" "$seeds" > "$build/$name.log" 2>&1
  code=$?
  grep -E 'stat::number_of_executed_units|stat::peak_rss_mb' "$build/$name.log" | sed 's/^/   /'
  if [ $code -ne 0 ]; then
    echo "   crashed (exit $code): see $build/$name.log and $artifacts/"
    status=1
  fi
done
exit $status
