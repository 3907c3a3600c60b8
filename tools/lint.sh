#!/usr/bin/env bash
# lint.sh BUILD: `make lint` — the house style, checked. Every C++ file in git (template
# sources and golden outputs excepted: they are data) must be formatted as .clang-format says,
# and the lint tests of BUILD must pass (lint/layering: the component graph). Exits non-zero
# on the first kind of problem found, after listing all of that kind.
set -uo pipefail
build=$(cd "$1" && pwd)
cd "$(dirname "$0")/.."
mapfile -t sources < <(git ls-files '*.cpp' '*.h' | grep -v -e '\.tpl\.' -e '^tests/golden/')
if ! clang-format --dry-run --Werror "${sources[@]}"; then
  echo "lint: files not formatted as .clang-format says; run: clang-format -i FILE..." >&2
  exit 1
fi
echo "lint: ${#sources[@]} C++ files formatted as .clang-format says"
ctest --test-dir "$build" -L '^lint$' --output-on-failure
