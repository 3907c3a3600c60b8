// Parsing and applying -W flags.
#include "ir/support/warning_options.h"

#include "ir/support/suggest.h"

namespace smachac {
namespace {

std::vector<std::string> kindNames() {
  std::vector<std::string> names;
  for (DiagKind kind : allDiagKinds()) names.emplace_back(diagKindInfo(kind).name);
  return names;
}

}  // namespace

std::optional<std::string> WarningOptions::apply(std::string_view flag) {
  if (flag.starts_with("-W")) flag.remove_prefix(2);
  if (flag == "error") {
    all_errors_ = true;
    return std::nullopt;
  }
  Setting setting = Setting::Enable;
  if (flag.starts_with("no-error=")) {
    setting = Setting::NotAsError;
    flag.remove_prefix(9);
  } else if (flag.starts_with("error=")) {
    setting = Setting::AsError;
    flag.remove_prefix(6);
  } else if (flag.starts_with("no-")) {
    setting = Setting::Disable;
    flag.remove_prefix(3);
  }
  std::optional<DiagKind> kind = diagKindByName(flag);
  if (!kind) {
    std::vector<std::string> names = kindNames();
    return "unknown diagnostic kind `" + std::string(flag) + "` in -W flag" +
           didYouMean(flag, names);
  }
  settings_[*kind].push_back(setting);
  return std::nullopt;
}

Severity WarningOptions::severityOf(DiagKind kind) const {
  const DiagKindInfo& info = diagKindInfo(kind);
  Severity severity = info.default_severity;
  bool as_error = all_errors_;
  bool not_as_error = false;
  if (auto it = settings_.find(kind); it != settings_.end()) {
    for (Setting setting : it->second) {
      switch (setting) {
        case Setting::Enable:
          if (severity == Severity::Ignored) severity = Severity::Warning;
          break;
        case Setting::Disable:
          if (severity != Severity::Error) severity = Severity::Ignored;
          break;
        case Setting::AsError:
          if (severity == Severity::Ignored) severity = Severity::Warning;
          as_error = true;
          not_as_error = false;
          break;
        case Setting::NotAsError:
          as_error = false;
          not_as_error = true;
          break;
      }
    }
  }
  if (severity == Severity::Error) {
    return (not_as_error && info.adjustable) ? Severity::Warning : Severity::Error;
  }
  if (severity == Severity::Warning && as_error) return Severity::Error;
  return severity;
}

}  // namespace smachac
