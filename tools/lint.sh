#!/usr/bin/env bash
# lint.sh BUILD: `make lint` — the house style, checked. Every C++ file in git (template
# sources and golden outputs excepted: they are data) must be formatted as .clang-format says,
# every C++ source BUILD compiles from the tree must name things as .clang-tidy says (run on
# BUILD's compile_commands.json; headers of the tree are checked through the sources that
# include them, generated code in BUILD is not), and the lint tests of BUILD must pass
# (lint/layering: the component graph). Exits non-zero on the first kind of problem found,
# after listing all of that kind.
set -uo pipefail
build=$(cd "$1" && pwd)
cd "$(dirname "$0")/.."
mapfile -t sources < <(git ls-files '*.cpp' '*.h' | grep -v -e '\.tpl\.' -e '^tests/golden/')
if ! clang-format --dry-run --Werror "${sources[@]}"; then
  echo "lint: files not formatted as .clang-format says; run: clang-format -i FILE..." >&2
  exit 1
fi
echo "lint: ${#sources[@]} C++ files formatted as .clang-format says"
root=$(pwd)
# Sources of the tree only (not what BUILD generates); clang-tidy parses with clang, which does
# not know some of GCC's warning flags in the compile database, hence -Wno-unknown-warning-option.
tree="^${root}/(backends|bench|checker|editors|frontend|ir|lsp|passes|refactor|sim|stdlib|templates|tests|tools)/"
# ... and the unity sources CMake makes of tree files compiled as one unit (the files they
# include are checked through them, as headers are).
unity="^${build}/.*/Unity/unity_.*\.cxx$"
if ! run-clang-tidy -clang-tidy-binary clang-tidy -p "$build" -j 2 -quiet \
    -header-filter "${tree}|/include_roots/" -extra-arg=-Wno-unknown-warning-option \
    "${tree}|${unity}" \
    > "$build/clang-tidy.log" 2>&1; then
  sed "s/\x1b\[[0-9;]*m//g" "$build/clang-tidy.log" | grep -E "error:|warning:" | sort -u >&2
  echo "lint: names not in the house style (.clang-tidy); whole log: $build/clang-tidy.log" >&2
  exit 1
fi
echo "lint: every C++ source of $build names things as .clang-tidy says"
ctest --test-dir "$build" -L '^lint$' --output-on-failure
