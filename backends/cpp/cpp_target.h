// The C++ target (`-target=cpp`): one self-contained C++20 translation unit with main(),
// rendered by SMACHA's generator from the built-in template set `cpp/` after the -I
// directories, for the runtime in stdlib/runtime (`smachac::runtime`). Backtick expressions
// are C++ (callbacks are lambdas taking `rt::UserData&`); a Python lambda is a located error.
// -c keeps the templates' comment blocks. With EmitOptions::library (-emit=library) it emits a
// header/source pair instead: `<namespace>::build()` returns the machine, no main() (see
// cpp_library.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/targets.h"

namespace smachac::backends::cpp {

std::optional<std::vector<OutputFile>> emitCpp(ir::Module&& module, EmitContext& context);

/// The template search path of the target: -I directories, then the built-in `cpp/` set.
generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs);

}  // namespace smachac::backends::cpp
