// The diagnostic data model: kinds (from diagnostic_kinds.def), severities and the reported
// diagnostics with their notes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/support/source_loc.h"

namespace smachac {

enum class DiagKind : uint16_t {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format) id,
#include "ir/support/diagnostic_kinds.def"
};

enum class Severity : uint8_t { Ignored, Note, Warning, Error };

struct DiagKindInfo {
  std::string_view name;  ///< kebab-case, as shown in `[...]` and used by -W flags
  Severity default_severity;
  bool adjustable;
  std::string_view format;
};

const DiagKindInfo& diagKindInfo(DiagKind kind);

/// The message format of a kind, at compile time: DiagnosticEmitter::emit checks the
/// arguments of every diagnostic against it when the call is compiled.
constexpr std::string_view diagKindFormat(DiagKind kind) {
  switch (kind) {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format) \
  case DiagKind::id:                                               \
    return format;
#include "ir/support/diagnostic_kinds.def"
  }
  return "";
}

/// The number of `{}` fields of a message format (`{{` is a literal brace).
constexpr size_t formatFieldCount(std::string_view format) {
  size_t count = 0;
  for (size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '{') continue;
    if (i + 1 < format.size() && format[i + 1] == '{') {
      ++i;
    } else {
      ++count;
    }
  }
  return count;
}
std::vector<DiagKind> allDiagKinds();
std::optional<DiagKind> diagKindByName(std::string_view name);
std::string_view severityName(Severity severity);
/// True for the kinds that say a file could not be read (the driver's exit code 2).
bool isIoError(DiagKind kind);

struct DiagNote {
  SourceLoc loc;
  std::string message;
};

struct Diagnostic {
  DiagKind kind;
  Severity severity;
  SourceLoc loc;
  std::string message;
  std::vector<DiagNote> notes;
  /// A fix-it: the text that fixes the problem when it replaces the span at `loc` (the name a
  /// "did you mean" suggests). For editors; the diagnostic printers do not show it.
  std::optional<std::string> fix;
};

}  // namespace smachac
