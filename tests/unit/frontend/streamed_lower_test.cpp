// Streamed lowering (FrontendOptions::stream_states, streamed_lowering.cpp) against the
// classic way (read the whole tree, then lower): the same module, printed, and the same
// diagnostics, for every script of the goldens and examples and for the cases where the
// streamed attempt has to stop early or start over.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/lower.h"
#include "ir/printer.h"

namespace fs = std::filesystem;

namespace {

/// What lowering a script gave: the printed module (or a marker) and every diagnostic.
std::string lowered(const std::string& path, const std::string* text, bool stream) {
  smachac::SourceManager sources;
  smachac::DiagnosticEmitter diags;
  smachac::frontend::FrontendOptions options;
  options.script_dirs = {fs::path(path).parent_path().string()};
  options.stream_states = stream;
  smachac::frontend::IncludeSites sites{{99, {}}};  // overwritten by every lowering
  options.include_sites = &sites;
  auto module = text ? smachac::frontend::lowerScriptText(path, *text, options, sources, diags)
                     : smachac::frontend::lowerScript(path, options, sources, diags);
  std::ostringstream out;
  out << (module ? smachac::ir::printModule(*module, sources) : "(no module)\n");
  for (const auto& [file, places] : sites) {
    out << "included " << file << ':';
    for (const smachac::SourceLoc& loc : places) out << ' ' << loc.line << ':' << loc.column;
    out << '\n';
  }
  for (const smachac::Diagnostic& d : diags.diagnostics()) {
    out << static_cast<int>(d.kind) << ' ' << d.loc.file << ':' << d.loc.line << ':' << d.loc.column
        << '+' << d.loc.length << ' ' << d.message << ' ' << d.fix.value_or("") << '\n';
    for (const smachac::DiagNote& n : d.notes) {
      out << "  note " << n.loc.file << ':' << n.loc.line << ':' << n.loc.column << ' ' << n.message
          << '\n';
    }
  }
  return out.str();
}

void checkSame(const std::string& path, const std::string* text = nullptr) {
  INFO(path);
  CHECK(lowered(path, text, true) == lowered(path, text, false));
}

void checkText(const std::string& text) {
  INFO(text);
  checkSame("streamed.yml", &text);
}

constexpr const char* kHead = "name: m\ntemplate: Base\noutcomes: [end]\nstates:\n";

}  // namespace

TEST_CASE("every golden and example script lowers the same streamed") {
  size_t scripts = 0;
  for (const char* dir : {"tests/golden", "examples"}) {
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SMACHAC_SOURCE_DIR) / dir)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".yml") continue;
      checkSame(entry.path().string());
      ++scripts;
    }
  }
  CHECK(scripts > 100);
}

TEST_CASE("a root key after `states` makes the streamed attempt start over") {
  checkText(std::string(kHead) + "  - A: {template: S, transitions: {ok: end}}\n" +
            "params: {x: 1}\n");
  checkText(std::string(kHead) + "  - A: {template: S, params: {y: [params, x]}}\n" +
            "params: {x: 1}\n");
  checkText(std::string(kHead) + "  - A: {template: S}\ns: []\n");
}

TEST_CASE("the fast reader giving up after streamed states makes the attempt start over") {
  checkText(std::string(kHead) + "  - A: {template: S, transitions: {ok: end}}\n" +
            "  - B:\n\ttemplate: S\n");
  checkText(std::string(kHead) + "  - A: {template: S, outcomes: x}\n" + "  - B: &b {}\n");
  checkText(std::string(kHead) + "  - A: {template: S}\n  - A: {template: S}\n  - [\n");
}

TEST_CASE("containers, inclusions and malformed entries stop streaming, in order") {
  checkText(std::string(kHead) + "  - A: {template: S, transitions: {ok: B}}\n" +
            "  - B:\n      template: StateMachine\n      outcomes: [end]\n" +
            "      states:\n        - C: {template: S}\n  - D: {template: S}\n");
  checkText(std::string(kHead) + "  - A: {template: S}\n  - B: {S: nowhere}\n  - C: {}\n");
  checkText(std::string(kHead) + "  - A: {template: S}\n  - [{B: {template: S}}]\n  - 3\n" +
            "  - {C: 1, D: 2}\n  - E: x\n");
}

TEST_CASE("diagnostics of streamed states and of the root come out once, in order") {
  checkText(std::string(kHead) + "  - A: {outcomes: x}\n  - B: {template: S, params: 3}\n" +
            "  - C: {template: S, T: S}\n");
  checkText("name: m\noutcomes: [end]\nbogus: 1\nstates:\n  - A: {template: S}\n");
  checkText("name: m\ntemplate: Base\nn: x\nstates:\n  - A: {template: S}\n");
  checkText("template: Base\nparams: {x: 1}\nstates:\n  - A: {template: S, p: {y: [params, z]}}\n");
}
