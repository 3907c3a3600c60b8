// Running a whole machine: run() for programs and tests, runMain() for a generated main().
//
//   int main(int argc, char** argv) {
//     rt::StateMachine sm({.outcomes = {"succeeded", "aborted"}});
//     ...                                   // sm.add(...)
//     return rt::runMain(sm, argc, argv);
//   }
#pragma once

#include <string>

#include "smachac/runtime/state.h"
#include "smachac/runtime/userdata.h"

namespace smachac::runtime {

struct RunResult {
  /// The root's outcome; `aborted` when the run failed.
  std::string outcome;
  /// Why the run failed (consistency problems, an exception in a state); empty when it did not.
  std::string error;
  bool ok() const { return error.empty(); }
};

/// Checks and executes `root`, emitting enter/exit events for it. The root's input keys are read
/// from `parent` and its output keys written back (nullptr: an empty scope). Never throws.
RunResult run(State& root, UserDataStore* parent = nullptr);

/// run() for a generated program. Flags:
///   --trace=json|log     stream the trace to stderr (JSON lines or readable lines)
///   --trace-file=PATH    write the JSON-lines trace to PATH
///   --seed=N             seed every RandomOutcomeState made without a seed
///   --quiet              do not print `outcome: <outcome>` on stdout
///   --print-userdata     then print `userdata: {...}`: the top container's final userdata
///                        in Python's spelling (keys sorted), for comparing runs of targets
/// SIGINT and SIGTERM preempt the machine (a second one ends the process). Returns the exit
/// code: 0 when the machine returned an outcome, 1 when it failed, 2 on a bad flag.
int runMain(State& root, int argc, char** argv);

}  // namespace smachac::runtime
