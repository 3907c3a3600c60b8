// Test helper: temporary scripts, loading and linting.
#include "tests/unit/refactor/scripts.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "frontend/lower.h"
#include "passes/pipeline.h"

namespace smachac::refactor::testing {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> kindsOf(const DiagnosticEmitter& diags) {
  std::vector<std::string> kinds;
  for (const Diagnostic& d : diags.diagnostics()) kinds.emplace_back(diagKindInfo(d.kind).name);
  return kinds;
}

}  // namespace

TempDir::TempDir() {
  std::string pattern = (fs::temp_directory_path() / "smachac_refactor.XXXXXX").string();
  REQUIRE(::mkdtemp(pattern.data()) != nullptr);
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& text) const {
  std::string file = (fs::path(path_) / name).string();
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

std::vector<std::string> Loaded::kinds() const { return kindsOf(diags); }

std::unique_ptr<Loaded> load(const std::string& path, std::vector<std::string> script_dirs) {
  auto loaded = std::make_unique<Loaded>();
  loaded->script = ScriptView::load(path, {std::move(script_dirs)}, loaded->sources, loaded->diags);
  return loaded;
}

std::optional<std::string> containFile(const std::string& path, const ContainRequest& request,
                                       std::vector<std::string>* kinds,
                                       std::vector<std::string> script_dirs) {
  std::unique_ptr<Loaded> loaded = load(path, std::move(script_dirs));
  std::optional<std::string> text;
  if (loaded->script) text = contain(*loaded->script, request, loaded->diags);
  if (kinds) *kinds = loaded->kinds();
  return text;
}

LintResult lint(const std::string& path, std::vector<std::string> script_dirs) {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<ir::Module> module =
      frontend::lowerScript(path, {std::move(script_dirs)}, sources, diags);
  if (module) {
    passes::PassContext context{sources, diags, "smach"};
    passes::runPipeline(*module, context, {});
  }
  return {diags.errorCount(), diags.warningCount(), kindsOf(diags)};
}

}  // namespace smachac::refactor::testing
