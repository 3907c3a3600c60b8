// Parsing and applying -W flags.
#include "ir/support/warning_options.h"

#include <algorithm>

#include "ir/support/suggest.h"

namespace smachac {
namespace {

constexpr std::string_view kGroups[] = {"all", "extra", "everything"};

/// The kinds a -W name stands for: one kind, or each kind of a group; empty when unknown.
std::vector<DiagKind> kindsNamed(std::string_view name) {
  if (std::optional<DiagKind> kind = diagKindByName(name)) return {*kind};
  std::vector<DiagKind> kinds;
  for (DiagKind kind : allDiagKinds()) {
    Severity severity = diagKindInfo(kind).default_severity;
    bool in_group = name == "everything" || (name == "extra" && severity != Severity::Error) ||
                    (name == "all" && severity == Severity::Warning);
    if (in_group) kinds.push_back(kind);
  }
  return kinds;
}

constexpr size_t kMaxSuggestions = 4;

/// "; did you mean `x`?" or "; did you mean one of `x`, `y`?": the kinds and groups close to
/// `name`, then those it begins.
std::string closeNames(std::string_view name) {
  std::vector<std::string> names = warningGroupNames();
  for (DiagKind kind : allDiagKinds()) names.emplace_back(diagKindInfo(kind).name);
  std::vector<std::string> close = closeMatches(name, names, kMaxSuggestions);
  for (const std::string& candidate : names) {
    bool listed = std::find(close.begin(), close.end(), candidate) != close.end();
    if (close.size() < kMaxSuggestions && !listed && candidate.starts_with(name)) {
      close.push_back(candidate);
    }
  }
  if (close.empty()) return "; `smachac --list-warnings` lists them";
  return (close.size() == 1 ? "; did you mean " : "; did you mean one of ") + quotedList(close) +
         "?";
}

}  // namespace

std::vector<std::string> warningGroupNames() {
  return std::vector<std::string>(std::begin(kGroups), std::end(kGroups));
}

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
  std::vector<DiagKind> kinds = kindsNamed(flag);
  if (kinds.empty()) {
    return "unknown diagnostic kind `" + std::string(flag) + "` in -W flag" + closeNames(flag);
  }
  for (DiagKind kind : kinds) settings_[kind].push_back(setting);
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
