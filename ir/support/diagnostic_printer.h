// Prints collected diagnostics in one of three formats:
//   text   path:line:col: severity: message [kind], the source line and a caret
//   json   one JSON array of {kind, severity, message, file, line, column, length, notes}
//   sarif  a SARIF 2.1.0 log with one run whose rules are the diagnostic kinds
#pragma once

#include <optional>
#include <ostream>
#include <span>
#include <string_view>

#include "ir/support/diagnostic.h"
#include "ir/support/source_manager.h"

namespace smachac {

enum class DiagnosticFormat { Text, Json, Sarif };

std::optional<DiagnosticFormat> parseDiagnosticFormat(std::string_view name);

void printDiagnostics(std::ostream& out, std::span<const Diagnostic> diagnostics,
                      const SourceManager& sources, DiagnosticFormat format);

/// The text form of one diagnostic with its notes (what `text` prints for it).
std::string formatDiagnosticText(const Diagnostic& diagnostic, const SourceManager& sources);

}  // namespace smachac
