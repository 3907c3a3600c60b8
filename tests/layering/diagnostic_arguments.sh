#!/usr/bin/env bash
# diagnostic_arguments.sh CXX ROOT: a diagnostic's arguments are checked when the call is
# compiled (ir/support/diagnostic_emitter.h). A call with the right arguments compiles; one
# with an argument too many or too few does not.
set -uo pipefail
cxx=$1 root=$2
probe() {  # probe KIND ARGS...: compile one emit call, print the compiler's output
  printf '#include "ir/support/diagnostic_emitter.h"\nvoid f(smachac::DiagnosticEmitter& d) {\n  d.emit<smachac::DiagKind::%s>(smachac::SourceLoc{}%s);\n}\n' "$1" "$2" |
    "$cxx" -std=c++20 -fsyntax-only -I "$root" -x c++ - 2>&1
}
fail=0
if ! out=$(probe DuplicateKey ', "x"'); then echo "FAIL a correct call does not compile: $out"; fail=1; fi
if out=$(probe DuplicateKey ', "x", "y"'); then
  echo "FAIL a call with an argument too many compiles"; fail=1
elif ! grep -q "must match its message" <<<"$out"; then
  echo "FAIL an argument too many is refused for another reason: $out"; fail=1
fi
if out=$(probe DuplicateKey ''); then echo "FAIL a call without its argument compiles"; fail=1; fi
[ $fail = 0 ] && echo "ok: diagnostic arguments are checked at compile time"
exit $fail
