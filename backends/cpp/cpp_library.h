// `-emit=library` of the C++ target: the template global `cpp_library` that turns Base's
// program into a source defining `<namespace>::build()`, and the header declaring it,
// rendered from the template `LibraryHeader.tpl.h` (found as every template: -I directories
// first, then the built-in `cpp/` set).
#pragma once

#include <optional>
#include <string>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/targets.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends::cpp {

/// The function the library defines: `std::unique_ptr<rt::StateMachine> build()`.
inline constexpr const char* kLibraryFunction = "build";

/// The global `cpp_library`: false for a program; for a library a dict with `namespace`,
/// `header` (the header's file name) and `function`.
tmpl::Value libraryGlobal(const std::optional<LibraryNames>& library);

/// The header of the library (stripped, one final newline), or nullopt after a template error
/// (reported). `env` has the global set.
std::optional<std::string> renderLibraryHeader(const ir::Module& module, tmpl::Environment& env,
                                               generator::ValueConverter& converter,
                                               const generator::TemplatePath& path,
                                               EmitContext& context);

}  // namespace smachac::backends::cpp
