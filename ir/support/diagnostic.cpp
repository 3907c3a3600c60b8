// The diagnostic kind table built from diagnostic_kinds.def, and the check, when this file is
// compiled, that every kind's and every note's format has one field per declared argument type
// and suits those types (also for an entry that no call uses yet).
#include "ir/support/diagnostic.h"

#include <array>

namespace smachac {
namespace {

constexpr DiagKindInfo kInfos[] = {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format, types) \
  {name, Severity::severity, adjustable, format},
#include "ir/support/diagnostic_kinds.def"
};

/// True when `format` has one field per type of `Kind`'s signature, and fmt accepts it for them.
template <auto Kind>
constexpr bool formatSuitsTypes() {
  using Signature = DiagSignatureOf<Kind>;
  return formatFieldCount(diagFormat(Kind)) == Signature::kCount &&
         Signature::checks([] { return diagFormat(Kind); });
}

#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format, types) \
  static_assert(formatSuitsTypes<DiagKind::id>(),                         \
                "diagnostic_kinds.def: the format of " #id " does not suit its types");
#include "ir/support/diagnostic_kinds.def"
#define SMACHAC_DIAGNOSTIC_NOTE(id, format, types)    \
  static_assert(formatSuitsTypes<DiagNoteKind::id>(), \
                "diagnostic_notes.def: the format of " #id " does not suit its types");
#include "ir/support/diagnostic_notes.def"

}  // namespace

const DiagKindInfo& diagKindInfo(DiagKind kind) { return kInfos[static_cast<size_t>(kind)]; }

std::vector<DiagKind> allDiagKinds() {
  std::vector<DiagKind> kinds;
  for (size_t i = 0; i < std::size(kInfos); ++i) kinds.push_back(static_cast<DiagKind>(i));
  return kinds;
}

std::optional<DiagKind> diagKindByName(std::string_view name) {
  for (size_t i = 0; i < std::size(kInfos); ++i) {
    if (kInfos[i].name == name) return static_cast<DiagKind>(i);
  }
  return std::nullopt;
}

std::string_view severityName(Severity severity) {
  switch (severity) {
    case Severity::Ignored:
      return "ignored";
    case Severity::Note:
      return "note";
    case Severity::Warning:
      return "warning";
    case Severity::Error:
      return "error";
  }
  return "error";
}

bool isIoError(DiagKind kind) {
  return kind == DiagKind::FileNotFound || kind == DiagKind::UnreadableFile;
}

}  // namespace smachac
