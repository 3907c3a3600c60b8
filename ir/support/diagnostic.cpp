// The diagnostic kind table built from diagnostic_kinds.def.
#include "ir/support/diagnostic.h"

#include <array>

namespace smachac {
namespace {

constexpr Severity Error = Severity::Error;
constexpr Severity Warning = Severity::Warning;
constexpr Severity Ignored = Severity::Ignored;

constexpr DiagKindInfo kInfos[] = {
#define SMACHAC_DIAGNOSTIC(id, name, severity, adjustable, format) \
  {name, severity, adjustable, format},
#include "ir/support/diagnostic_kinds.def"
};

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
