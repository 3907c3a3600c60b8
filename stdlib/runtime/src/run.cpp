// run(): executes a root state and turns every failure into an `aborted` result.
#include "smachac/runtime/run.h"

#include "smachac/runtime/errors.h"
#include "smachac/runtime/trace.h"

namespace smachac::runtime {

namespace {

RunResult failed(const State& root, std::string message, bool traced) {
  if (!traced && root.traceSink() != nullptr) {
    root.traceSink()->write({.kind = TraceKind::Error, .state = root.path(), .message = message});
  }
  return {.outcome = "aborted", .error = std::move(message)};
}

}  // namespace

RunResult run(State& root, UserDataStore* parent) {
  UserDataStore empty;
  UserData view(parent != nullptr ? *parent : empty, root);
  TraceSink* sink = root.traceSink();
  view.trackWrites(sink != nullptr);
  try {
    if (sink != nullptr) sink->write({.kind = TraceKind::Enter, .state = root.path()});
    std::string outcome = root.execute(view);
    root.recallPreempt();  // a request nothing serviced ends with this run
    if (sink != nullptr) {
      sink->write({.kind = TraceKind::Exit,
                   .state = root.path(),
                   .outcome = outcome,
                   .written = &view.written()});
    }
    return {.outcome = std::move(outcome), .error = {}};
  } catch (const ExecutionError& e) {
    return failed(root, e.what(), true);
  } catch (const Error& e) {
    return failed(root, e.what(), false);
  } catch (const std::exception& e) {
    return failed(root, "state `" + root.displayName() + "` failed: " + e.what(), false);
  } catch (...) {
    return failed(root, "state `" + root.displayName() + "` failed: unknown exception", false);
  }
}

}  // namespace smachac::runtime
