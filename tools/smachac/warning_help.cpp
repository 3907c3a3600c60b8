// The -W help text and the list of diagnostic kinds.
#include "tools/smachac/warning_help.h"

#include <fmt/core.h>

#include <iostream>

#include "ir/support/diagnostic.h"

namespace smachac::driver {
namespace {

/// How a kind is reported when no -W flag names it, and which -W flags change that.
std::string_view defaultOf(const DiagKindInfo& info) {
  switch (info.default_severity) {
    case Severity::Error:
      return info.adjustable ? "error, -Wno-error=<kind> makes it a warning" : "error";
    case Severity::Warning:
      return "warning (-Wall)";
    case Severity::Ignored:
    case Severity::Note:
      return "off (-Wextra)";
  }
  return "error";
}

}  // namespace

std::string warningFlagsHelp() {
  return "Diagnostics (-W flags, the last one naming a kind wins):\n"
         "  -W<kind>, -Wno-<kind>     enable or silence the warning <kind>\n"
         "  -Werror                   every warning is an error\n"
         "  -Werror=<kind>            that warning is an error\n"
         "  -Wno-error=<kind>         that warning stays a warning under -Werror; a check's\n"
         "                            error (marked so by --list-warnings) becomes a warning\n"
         "  -Wall                     the warnings on by default\n"
         "  -Wextra                   -Wall and the warnings off by default\n"
         "  -Weverything              every kind (errors stay errors)\n"
         "  Groups take every spelling: -Wno-all, -Werror=extra, ...\n"
         "  --list-warnings           list every kind, its default and its group\n";
}

void printWarningList() {
  for (DiagKind kind : allDiagKinds()) {
    const DiagKindInfo& info = diagKindInfo(kind);
    std::cout << fmt::format("{:<36} {}\n", info.name, defaultOf(info));
  }
}

}  // namespace smachac::driver
