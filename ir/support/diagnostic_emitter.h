// The one channel for problems in the user's input. Checks call emit<Kind>() with a kind from
// diagnostic_kinds.def and the arguments of its message, then note<Note>() with a note from
// diagnostic_notes.def and its arguments; both are checked against the types the .def entry
// declares when the call is compiled (a wrong count or type does not build). The emitter
// applies -W options and collects the diagnostics for a DiagnosticPrinter.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ir/support/diagnostic.h"
#include "ir/support/warning_options.h"

namespace smachac {

class DiagnosticEmitter {
 public:
  explicit DiagnosticEmitter(WarningOptions options = {}) : options_(std::move(options)) {}

  template <DiagKind Kind, typename... Args>
  void emit(SourceLoc loc, const Args&... args) {
    report(Kind, loc, diagMessage<Kind>(args...));
  }

  /// Attaches a note to the diagnostic emitted last (dropped if that one was silenced).
  template <DiagNoteKind Note, typename... Args>
  void note(SourceLoc loc, const Args&... args) {
    if (!last_dropped_) attach(makeNote<Note>(loc, args...));
  }
  /// Gives the diagnostic emitted last a fix-it, the replacement of its span (Diagnostic::fix);
  /// nothing when `replacement` is empty or that diagnostic was silenced.
  void fixIt(std::optional<std::string> replacement);

  bool hasErrors() const { return error_count_ > 0; }
  size_t errorCount() const { return error_count_; }
  size_t warningCount() const { return warning_count_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  /// Replaces the diagnostics from index `first` on (already filtered by -W) and recounts.
  void replaceFrom(size_t first, std::vector<Diagnostic> replacement);

 private:
  void report(DiagKind kind, SourceLoc loc, std::string message);
  void attach(DiagNote note);

  WarningOptions options_;
  std::vector<Diagnostic> diagnostics_;
  bool last_dropped_ = false;
  size_t error_count_ = 0;
  size_t warning_count_ = 0;
};

}  // namespace smachac
