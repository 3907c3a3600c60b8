// Test helper: lowers a script given as text (through a temporary file, as the driver would)
// and runs passes on it, keeping the diagnostics for inspection.
#pragma once

#include <doctest/doctest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"
#include "passes/pass.h"

namespace smachac::passes::testing {

struct Compiled {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<ir::Module> module;

  explicit Compiled(WarningOptions options) : diags(std::move(options)) {}
  /// The kebab-case kinds of the diagnostics reported so far, in order.
  std::vector<std::string> kinds() const;
  /// "line:col kind" of each diagnostic, in order.
  std::vector<std::string> located() const;
  /// The module in its text form.
  std::string ir() const;
  PassContext context(std::string target = "ir") { return {sources, diags, std::move(target)}; }
};

/// Lowers `script`; `flags` are -W flags ("-Wunused-userdata-key", ...).
std::unique_ptr<Compiled> lower(const std::string& script,
                                const std::vector<std::string>& flags = {});

/// Lowers `script` and runs one check on it for `target`.
std::unique_ptr<Compiled> check(const std::string& script, CheckFn check,
                                const std::string& target = "ir",
                                const std::vector<std::string>& flags = {});

/// The child of the root named `name` (or of the state at `path`, names joined by '/').
ir::StateId find(const ir::Module& module, const std::string& path);

}  // namespace smachac::passes::testing

/// Lists of strings print as ["a", "b"] in failed assertions.
template <>
struct doctest::StringMaker<std::vector<std::string>> {
  static doctest::String convert(const std::vector<std::string>& items) {
    std::string text = "[";
    for (const std::string& item : items) text += (text.size() > 1 ? ", \"" : "\"") + item + "\"";
    return (text + "]").c_str();
  }
};
