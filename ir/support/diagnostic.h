// The diagnostic data model: kinds (from diagnostic_kinds.def) and notes (from
// diagnostic_notes.def) with their message formats and argument types, severities, and the
// reported diagnostics with their notes. diagMessage<Kind>(args...) formats a kind's or a
// note's message after checking the arguments against the declared types at compile time.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/support/diagnostic_signature.h"
#include "ir/support/source_loc.h"

namespace smachac {

enum class DiagKind : uint16_t {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format, types) id,
#include "ir/support/diagnostic_kinds.def"
};

enum class DiagNoteKind : uint16_t {
#define SMACHAC_DIAGNOSTIC_NOTE(id, format, types) id,
#include "ir/support/diagnostic_notes.def"
};

enum class Severity : uint8_t { Ignored, Note, Warning, Error };

struct DiagKindInfo {
  std::string_view name;  ///< kebab-case, as shown in `[...]` and used by -W flags
  Severity default_severity;
  bool adjustable;
  std::string_view format;
};

const DiagKindInfo& diagKindInfo(DiagKind kind);

/// The message format of a kind, at compile time.
constexpr std::string_view diagFormat(DiagKind kind) {
  switch (kind) {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format, types) \
  case DiagKind::id:                                                      \
    return format;
#include "ir/support/diagnostic_kinds.def"
  }
  return "";
}

/// The message format of a note, at compile time.
constexpr std::string_view diagFormat(DiagNoteKind note) {
  switch (note) {
#define SMACHAC_DIAGNOSTIC_NOTE(id, format, types) \
  case DiagNoteKind::id:                           \
    return format;
#include "ir/support/diagnostic_notes.def"
  }
  return "";
}

/// The declared argument types of a kind or a note: a DiagSignature<types...>.
template <auto Kind>
struct DiagSignatureOf;
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format, types) \
  template <>                                                             \
  struct DiagSignatureOf<DiagKind::id> : DiagSignature<SMACHAC_DIAG_TYPES(types)> {};
#include "ir/support/diagnostic_kinds.def"
#define SMACHAC_DIAGNOSTIC_NOTE(id, format, types) \
  template <>                                      \
  struct DiagSignatureOf<DiagNoteKind::id> : DiagSignature<SMACHAC_DIAG_TYPES(types)> {};
#include "ir/support/diagnostic_notes.def"

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

/// The message of `Kind` (a DiagKind or a DiagNoteKind) for `args`, which must match the types
/// its .def entry declares: in number, and each converting without narrowing.
template <auto Kind, typename... Given>
std::string diagMessage(const Given&... args) {
  using Signature = DiagSignatureOf<Kind>;
  static_assert(sizeof...(Given) == Signature::kCount,
                "a diagnostic takes as many arguments as its .def entry declares types");
  static_assert(sizeof...(Given) != Signature::kCount || Signature::template accepts<Given...>(),
                "each argument of a diagnostic must convert, without narrowing, to the type "
                "its .def entry declares");
  return Signature::format(diagFormat(Kind), args...);
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

/// A note of kind `Note` at `loc`, its arguments checked as diagMessage checks them.
template <DiagNoteKind Note, typename... Given>
DiagNote makeNote(SourceLoc loc, const Given&... args) {
  return {loc, diagMessage<Note>(args...)};
}

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
