// lowerScript on files written to a temporary directory.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "frontend/lower.h"
#include "ir/printer.h"

namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("smachac_lower_test_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    fs::create_directories((path / name).parent_path());
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
};

}  // namespace

TEST_CASE("containers, transitions and sub-scripts lower into one graph") {
  TempDir dir;
  dir.write("lib/sub.yml",
            "- ANY:\n    template: StateMachine\n    outcomes: [done]\n"
            "    states:\n      - IN: {template: S, transitions: {ok: done}}\n");
  std::string main = dir.write("main.yml",
                               "name: m\ntemplate: Base\noutcomes: [end]\nstates:\n"
                               "  - A: {template: S, transitions: {ok: B}}\n"
                               "  - B: {script: sub, transitions: {done: end}}\n");
  smachac::SourceManager sources;
  smachac::DiagnosticEmitter diags;
  smachac::frontend::FrontendOptions options{{(dir.path / "lib").string()}};
  auto module = smachac::frontend::lowerScript(main, options, sources, diags);
  REQUIRE(module.has_value());
  CHECK(diags.diagnostics().empty());
  CHECK(module->stateCount() == 4);
  smachac::ir::StateId b = module->findChild(module->root(), "B");
  REQUIRE(b.valid());
  CHECK(module->state(b).kind == smachac::ir::StateKind::StateMachine);
  CHECK(module->path(module->state(b).children[0]) == "m/B/IN");
  const auto& a = module->state(module->findChild(module->root(), "A"));
  CHECK(a.transitions[0].target_kind == smachac::ir::TargetKind::Sibling);
  CHECK(a.transitions[0].target_state == b);
  CHECK(module->files().size() == 2);
}

TEST_CASE("errors in several states are all reported and no module is returned") {
  TempDir dir;
  std::string main = dir.write("bad.yml",
                               "name: m\ntemplate: Base\nstates:\n  - A: {outcomes: x}\n"
                               "  - B: {template: S, params: 3}\n  - C: {script: nowhere}\n");
  smachac::SourceManager sources;
  smachac::DiagnosticEmitter diags;
  auto module = smachac::frontend::lowerScript(main, {}, sources, diags);
  CHECK_FALSE(module.has_value());
  CHECK(diags.errorCount() == 4);  // outcomes type, A's template, params type, C not found
}
