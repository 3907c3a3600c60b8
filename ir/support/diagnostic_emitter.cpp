// DiagnosticEmitter: severity resolution and collection.
#include "ir/support/diagnostic_emitter.h"

#include <algorithm>

namespace smachac {

void DiagnosticEmitter::report(DiagKind kind, SourceLoc loc, std::string message) {
  Severity severity = options_.severityOf(kind);
  last_dropped_ = severity == Severity::Ignored;
  if (last_dropped_) return;
  if (severity == Severity::Error) ++error_count_;
  if (severity == Severity::Warning) ++warning_count_;
  diagnostics_.push_back({kind, severity, loc, std::move(message), {}, std::nullopt});
}

void DiagnosticEmitter::attach(DiagNote note) {
  if (last_dropped_ || diagnostics_.empty()) return;
  diagnostics_.back().notes.push_back(std::move(note));
}

void DiagnosticEmitter::fixIt(std::optional<std::string> replacement) {
  if (last_dropped_ || diagnostics_.empty() || !replacement) return;
  diagnostics_.back().fix = std::move(replacement);
}

void DiagnosticEmitter::replaceFrom(size_t first, std::vector<Diagnostic> replacement) {
  diagnostics_.resize(std::min(first, diagnostics_.size()));
  for (Diagnostic& d : replacement) diagnostics_.push_back(std::move(d));
  error_count_ = warning_count_ = 0;
  for (const Diagnostic& d : diagnostics_) {
    if (d.severity == Severity::Error) ++error_count_;
    if (d.severity == Severity::Warning) ++warning_count_;
  }
}

}  // namespace smachac
