// What the driver says about diagnostics: the -W flags in --help, and --list-warnings.
#pragma once

#include <string>

namespace smachac::driver {

/// The -W flags and groups, as a footer for the --help of compile, lint and lsp.
std::string warningFlagsHelp();

/// --list-warnings: every diagnostic kind, its default and what -W can do with it.
void printWarningList();

}  // namespace smachac::driver
