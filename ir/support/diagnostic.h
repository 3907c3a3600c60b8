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
};

}  // namespace smachac
