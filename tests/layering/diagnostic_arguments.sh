#!/usr/bin/env bash
# diagnostic_arguments.sh CXX ROOT: a diagnostic's and a note's arguments are checked against
# the types their .def entry declares when the call is compiled (ir/support/diagnostic.h,
# diagnostic_signature.h), and so is a message format against its types. Each probe is a small
# source: the correct calls must compile, each wrong one must fail, for the reason named.
set -uo pipefail
cxx=$1 root=$2
fail=0

compile() {  # compile BODY: compile a function holding BODY, print the compiler's output
  printf '#include "ir/support/diagnostic_emitter.h"
using namespace smachac;
void probe(DiagnosticEmitter& d, int count) {
  (void)d;
  (void)count;
  %s
}
' "$1" | "$cxx" -std=c++20 -fsyntax-only -I "$root" -x c++ - 2>&1
}

accepts() {  # accepts WHAT BODY
  local out
  if ! out=$(compile "$2"); then
    echo "FAIL $1 does not compile:"
    echo "$out" | grep -m5 error
    fail=1
  fi
}

refuses() {  # refuses WHAT REASON BODY: BODY must not compile, with REASON in the errors
  local out
  if out=$(compile "$3"); then
    echo "FAIL $1 compiles"
    fail=1
  elif ! grep -q -- "$2" <<<"$out"; then
    echo "FAIL $1 is refused, but not for \"$2\":"
    echo "$out" | grep -m5 error
    fail=1
  fi
}

count_reason="as many arguments as its .def entry declares"
type_reason="must convert, without narrowing"

accepts "a correct emit" 'd.emit<DiagKind::DuplicateKey>(SourceLoc{}, std::string("x"));'
accepts "a number for a size_t" 'd.emit<DiagKind::NestingTooDeep>(SourceLoc{}, size_t{100});'
accepts "a foreign message" 'd.emit<DiagKind::YamlSyntax>(SourceLoc{}, ForeignMessage("x"));'
accepts "a choice" 'd.emit<DiagKind::InvalidEncoding>(SourceLoc{}, EncodingProblem::NulByte);'
accepts "a correct note" 'd.note<DiagNoteKind::LookedFor>(SourceLoc{}, "x.yml");'
accepts "a note without arguments" 'd.note<DiagNoteKind::IncludedFromHere>(SourceLoc{});'
accepts "a correct makeNote" 'DiagNote n = makeNote<DiagNoteKind::KeySetHere>(SourceLoc{}, "k");'

refuses "an argument too many" "$count_reason" \
  'd.emit<DiagKind::DuplicateKey>(SourceLoc{}, "x", "y");'
refuses "an argument too few" "$count_reason" 'd.emit<DiagKind::DuplicateKey>(SourceLoc{});'
refuses "a number for text" "$type_reason" 'd.emit<DiagKind::DuplicateKey>(SourceLoc{}, 42);'
refuses "text for a number" "$type_reason" 'd.emit<DiagKind::NestingTooDeep>(SourceLoc{}, "9");'
refuses "a narrowing int for a size_t" "$type_reason" \
  'd.emit<DiagKind::NestingTooDeep>(SourceLoc{}, count);'
refuses "plain text for a foreign message" "$type_reason" \
  'd.emit<DiagKind::YamlSyntax>(SourceLoc{}, "x");'
refuses "a choice of another kind" "$type_reason" \
  'd.emit<DiagKind::InvalidEncoding>(SourceLoc{}, YamlSyntaxHint::CloseList);'
refuses "a note with an argument too many" "$count_reason" \
  'd.note<DiagNoteKind::IncludedFromHere>(SourceLoc{}, "x");'
refuses "a note with a number for text" "$type_reason" \
  'd.note<DiagNoteKind::LookedFor>(SourceLoc{}, 3.5);'
refuses "a free-text note" "no matching" 'd.note(SourceLoc{}, "looked elsewhere");'

# The check of each .def entry's format against its types (diagnostic.cpp runs it for all).
accepts "a format that suits its types" \
  'static_assert(DiagSignature<std::string_view, size_t>::checks([] { return "`{}`: {}"; }));'
refuses "a format with a field too many" "argument not found" \
  'static_assert(DiagSignature<std::string_view>::checks([] { return "`{}` and `{}`"; }));'
refuses "a number format for text" "invalid type specifier" \
  'static_assert(DiagSignature<std::string_view>::checks([] { return "{:d}"; }));'

[ $fail = 0 ] && echo "ok: diagnostic and note arguments are checked at compile time"
exit $fail
