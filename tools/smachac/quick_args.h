// The compile command lines that build systems and benchmarks run, read without CLI11: its
// set-up of the compile command's twenty-odd options was a tenth of a cold compile (0.27 M of
// 2.9 M instructions), paid before any work. Rules: only scripts, -target, -o, -I, -S, -c,
// -i, -O and -fsyntax-only, each option once (-I and -S repeatable), a value as `--name=V`
// or as the next argument, never empty or starting with `-`. Any other line is not read
// here (nullopt) and goes to CLI11 as before, so help, errors and every rarer form keep
// CLI11's behaviour; a line read here means to CLI11 what it means here
// (tests/e2e/test_driver.py compares the two).
#pragma once

#include <optional>

#include "tools/smachac/commands.h"
#include "tools/smachac/compile_options.h"

namespace smachac::driver {

/// The options of `args` (normalised, -W flags taken out), or nullopt for CLI11 to read.
std::optional<CompileOptions> readQuickCompileLine(const Args& args);

}  // namespace smachac::driver
