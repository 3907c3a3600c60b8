// The one channel for problems in the user's input. Checks call emit<Kind>() with a kind from
// diagnostic_kinds.def and the arguments of its message, which fmt checks against the kind's
// format when the call is compiled (a wrong count or an unformattable argument does not
// build); the emitter applies -W options and collects the diagnostics for a
// DiagnosticPrinter.
#pragma once

#include <fmt/core.h>

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
    static_assert(sizeof...(Args) == formatFieldCount(diagKindFormat(Kind)),
                  "the arguments of a diagnostic must match its message's {} fields");
    report(Kind, loc,
           fmt::format(fmt::format_string<const Args&...>(diagKindFormat(Kind)), args...));
  }

  /// Attaches a note to the diagnostic emitted last (dropped if that one was silenced).
  void note(SourceLoc loc, std::string message);
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

  WarningOptions options_;
  std::vector<Diagnostic> diagnostics_;
  bool last_dropped_ = false;
  size_t error_count_ = 0;
  size_t warning_count_ = 0;
};

}  // namespace smachac
