// `smachac contain SCRIPT NAME StateMachine|Concurrence STATE... [-o out.yml] [-S dir]
// [--default-target T]`: replaces consecutive root states by a new container
// (refactor/contain.h has the rules). The output defaults to SMACHA's
// `smacha_contain_output.yml`; `-o -` writes to standard output. The result must load
// again: a contained script that does not is a bug in smachac.
#include <fmt/core.h>

#include <iostream>
#include <set>

#include "frontend/lower.h"
#include "ir/support/check.h"
#include "refactor/contain.h"
#include "tools/smachac/output.h"
#include "tools/smachac/script_tool.h"

namespace smachac::driver {
namespace {

struct ContainOptions {
  std::string script;
  std::string name;
  std::string type;
  std::vector<std::string> states;
  std::string output = "smacha_contain_output.yml";
  std::string default_target;
};

void setUp(CLI::App& app, ContainOptions& o) {
  app.add_option("script", o.script, "the script")->required()->type_name("SCRIPT");
  app.add_option("name", o.name, "the new container's name")->required()->type_name("NAME");
  app.add_option("type", o.type, "the container's template")
      ->required()
      ->check(CLI::IsMember({"StateMachine", "Concurrence"}))
      ->type_name("StateMachine|Concurrence");
  app.add_option("states", o.states, "consecutive root states, in script order")
      ->required()
      ->type_name("STATE...");
  app.add_option("-o,--output", o.output, "output script (default smacha_contain_output.yml)");
  app.add_option("--default-target", o.default_target,
                 "Concurrence: where the default outcome goes (default: the target of the "
                 "first container outcome)");
}

std::optional<std::string> checkRequest(const ContainOptions& o) {
  if (o.name.empty()) return "the container name must not be empty";
  std::set<std::string> seen;
  for (const std::string& state : o.states) {
    if (!seen.insert(state).second) return fmt::format("state `{}` is given twice", state);
  }
  if (!o.default_target.empty() && o.type != "Concurrence") {
    return "--default-target is only for a Concurrence";
  }
  return std::nullopt;
}

refactor::ContainRequest request(const ContainOptions& o) {
  refactor::ContainRequest r{o.name, ir::StateKind::StateMachine, o.states, {}};
  if (o.type == "Concurrence") r.kind = ir::StateKind::Concurrence;
  if (!o.default_target.empty()) r.default_target = o.default_target;
  return r;
}

/// A contained script must load again: anything else is a bug here, not in the input.
void checkReloads(const std::string& path, const std::string& text,
                  const std::vector<std::string>& script_dirs) {
  SourceManager sources;
  DiagnosticEmitter diags;
  bool loads = frontend::lowerScriptText(path, text, {script_dirs}, sources, diags).has_value();
  SMACHAC_CHECK(loads && !diags.hasErrors(), "the contained script does not load again");
}

}  // namespace

int runContain(const Args& args) {
  ScriptTool tool("contain", "smachac contain: replace consecutive root states by a new container");
  ContainOptions o;
  setUp(tool.app(), o);
  if (std::optional<int> code = tool.start(args, [&] { return checkRequest(o); })) return *code;
  std::optional<refactor::ScriptView> script = tool.load(o.script);
  std::optional<std::string> text;
  if (script) text = refactor::contain(*script, request(o), tool.session().diags());
  if (std::optional<int> code = tool.report(text.has_value())) return *code;
  checkReloads(o.script, *text, tool.scriptDirs());
  if (std::optional<std::string> error = writeFileAtomically(o.output, *text)) {
    std::cerr << "smachac: error: " << *error << "\n";
    return kExitUsageError;
  }
  return kExitOk;
}

}  // namespace smachac::driver
