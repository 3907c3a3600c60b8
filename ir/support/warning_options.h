// -W flags: which diagnostics are reported and at which severity.
//   -Werror             every warning is an error
//   -W<kind>            enable a warning (also one that is off by default)
//   -Wno-<kind>         silence a warning
//   -Werror=<kind>      that warning is an error
//   -Wno-error=<kind>   that warning stays a warning under -Werror; an adjustable error
//                       becomes a warning
// A group name stands for each kind in it, in every spelling (-Wall, -Wno-extra, ...):
//   all         the warnings on by default (default severity Warning)
//   extra       all, and the warnings off by default (default severity Ignored)
//   everything  every kind
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/support/diagnostic.h"

namespace smachac {

/// The -W group names, in order of size: all, extra, everything.
std::vector<std::string> warningGroupNames();

class WarningOptions {
 public:
  /// Applies one flag (with its leading "-W"). Returns an error message for an unknown flag.
  std::optional<std::string> apply(std::string_view flag);

  /// The severity a diagnostic of `kind` is reported with (Ignored: not reported).
  Severity severityOf(DiagKind kind) const;

 private:
  enum class Setting { Enable, Disable, AsError, NotAsError };
  bool all_errors_ = false;
  std::map<DiagKind, std::vector<Setting>> settings_;
};

}  // namespace smachac
