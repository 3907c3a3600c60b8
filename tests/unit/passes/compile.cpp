// Test helper: scripts from text, through temporary files.
#include "tests/unit/passes/compile.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "frontend/lower.h"
#include "ir/printer.h"

namespace smachac::passes::testing {

namespace fs = std::filesystem;

std::vector<std::string> Compiled::kinds() const {
  std::vector<std::string> names;
  for (const Diagnostic& d : diags.diagnostics()) {
    names.emplace_back(diagKindInfo(d.kind).name);
  }
  return names;
}

std::vector<std::string> Compiled::located() const {
  std::vector<std::string> names;
  for (const Diagnostic& d : diags.diagnostics()) {
    names.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " +
                    std::string(diagKindInfo(d.kind).name));
  }
  return names;
}

std::string Compiled::ir() const { return ir::printModule(*module, sources); }

std::unique_ptr<Compiled> lower(const std::string& script, const std::vector<std::string>& flags) {
  static int counter = 0;
  WarningOptions options;
  for (const std::string& flag : flags) REQUIRE_FALSE(options.apply(flag).has_value());
  auto compiled = std::make_unique<Compiled>(std::move(options));
  fs::path path = fs::temp_directory_path() / ("smachac_passes_test_" + std::to_string(::getpid()) +
                                               "_" + std::to_string(counter++) + ".yml");
  std::ofstream(path) << script;
  compiled->module = frontend::lowerScript(path.string(), {}, compiled->sources, compiled->diags);
  fs::remove(path);
  REQUIRE(compiled->module.has_value());
  return compiled;
}

std::unique_ptr<Compiled> check(const std::string& script, CheckFn fn, const std::string& target,
                                const std::vector<std::string>& flags) {
  std::unique_ptr<Compiled> compiled = lower(script, flags);
  PassContext context = compiled->context(target);
  fn(*compiled->module, context);
  return compiled;
}

ir::StateId find(const ir::Module& module, const std::string& path) {
  ir::StateId id = module.root();
  size_t start = 0;
  while (id.valid() && start <= path.size()) {
    size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    id = module.findChild(id, path.substr(start, end - start));
    start = end + 1;
  }
  return id;
}

}  // namespace smachac::passes::testing
