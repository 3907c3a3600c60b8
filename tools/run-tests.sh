#!/usr/bin/env bash
# run-tests.sh BUILD JOBS: the test suite of `make test`. ctest runs every test; then the reasons
# for what did not run are printed (ctest itself only says "Skipped"), then one `skip:` line for
# each framework that is missing here with the commands that provide it (tools/frameworks), and
# ctest's summary line is repeated last. Exits with ctest's status.
set -uo pipefail
build=$1 jobs=$2
ctest --test-dir "$build" --output-on-failure -j "$jobs" --output-junit ctest-junit.xml 2>&1 |
  tee "$build/ctest.log"
status=${PIPESTATUS[0]}
python3 "$(dirname "$0")/print-skips.py" "$build/ctest-junit.xml"
/usr/bin/python3 "$(dirname "$0")/frameworks" --missing
grep -E '^[0-9]+% tests passed' "$build/ctest.log" | tail -n 1
exit "$status"
