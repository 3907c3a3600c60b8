// `smachac [-target=T] script.yml [-o out]` and `-fsyntax-only`: compile scripts to a target.
#include <fmt/core.h>

#include <iostream>

#include "backends/targets.h"
#include "ir/support/version.h"
#include "tools/smachac/args.h"
#include "tools/smachac/depfile.h"
#include "tools/smachac/output.h"
#include "tools/smachac/session.h"

namespace smachac::driver {
namespace {

struct CompileOptions {
  CommonOptions common;
  std::vector<std::string> inputs;
  std::string output;
  std::string depfile;
  bool syntax_only = false;
  bool comments = false;
  bool introspection = false;
  bool list_targets = false;
  int flexbe_ros = 2;
};

std::string targetNames() {
  std::string names;
  for (const backends::Target& t : backends::targets()) {
    names += (names.empty() ? "" : ", ") + std::string(t.name);
  }
  return names;
}

void setUp(CLI::App& app, CompileOptions& o) {
  app.description(
      "smachac: a compiler for SMACHA state-machine scripts.\n"
      "Subcommands: lint, render, help, contain, extract (run `smachac <subcommand> --help`).");
  app.set_version_flag("--version", fmt::format("smachac {}", kVersion));
  app.add_option("inputs", o.inputs, "script files")->type_name("SCRIPT");
  app.add_option("--target", o.common.target, "output target: " + targetNames());
  app.add_option("-o,--output", o.output, "output file (default: standard output)");
  app.add_flag("--fsyntax-only", o.syntax_only, "parse and check only; write nothing");
  app.add_flag("-c,--comments", o.comments, "include the templates' comment blocks");
  app.add_flag("-i,--introspection", o.introspection,
               "include the SMACH introspection server (ROS bases)");
  app.add_option("--flexbe-ros", o.flexbe_ros, "FlexBE target: ROS version 1 or 2 (default 2)")
      ->check(CLI::IsMember({1, 2}));
  app.add_option("--depfile", o.depfile,
                 "also write a Make-style dependency file of the output (needs -o)")
      ->type_name("PATH");
  app.add_flag("--list-targets", o.list_targets, "list the output targets and exit");
  addCommonOptions(app, o.common);
}

int usageError(const std::string& message) {
  std::cerr << "smachac: error: " << message << "\n";
  return kExitUsageError;
}

int checkOnly(Session& session, const std::vector<std::string>& inputs) {
  bool ok = true;
  for (const std::string& input : inputs) ok = session.compile(input).has_value() && ok;
  session.printDiagnostics();
  return ok && !session.diags().hasErrors() ? kExitOk : kExitInputError;
}

int emit(Session& session, const CompileOptions& o, const backends::Target& target) {
  std::optional<ir::Module> module = session.compile(o.inputs.front());
  std::optional<std::vector<backends::OutputFile>> files;
  backends::EmitOptions emit_options{.template_dirs = o.common.template_dirs,
                                     .comments = o.comments,
                                     .introspection = o.introspection,
                                     .flexbe_ros = o.flexbe_ros,
                                     .output = o.output};
  if (module) {
    backends::EmitContext context{session.sources(), session.diags(), emit_options};
    files = target.emit(*module, context);
  }
  session.printDiagnostics();
  if (!files || session.diags().hasErrors()) return kExitInputError;
  if (!o.depfile.empty()) {
    if (std::optional<std::string> error =
            writeDepfile(o.depfile, o.output, *module, session.sources(), o.common.template_dirs)) {
      std::cerr << "smachac: error: " << *error << "\n";
      return kExitUsageError;
    }
  }
  for (const backends::OutputFile& file : *files) {
    std::string path = o.output.empty() ? "-" : o.output;
    if (!file.name.empty()) path = (o.output.empty() ? "." : o.output) + "/" + file.name;
    if (std::optional<std::string> error = writeFileAtomically(path, file.content)) {
      std::cerr << "smachac: error: " << *error << "\n";
      return kExitUsageError;
    }
  }
  return kExitOk;
}

}  // namespace

int runCompile(const Args& raw_args) {
  Args args = raw_args;
  std::vector<std::string> warning_flags = takeWarningFlags(args);
  CLI::App app;
  CompileOptions o;
  setUp(app, o);
  if (std::optional<int> code = parseArgs(app, args)) return *code;
  if (o.common.list_passes) return printPassList(), kExitOk;
  if (o.list_targets) {
    for (const backends::Target& t : backends::targets()) {
      std::cout << fmt::format("{:<10} {}\n", t.name, t.description);
    }
    return kExitOk;
  }
  if (o.inputs.empty()) return usageError("no input script (see `smachac --help`)");
  Session session;
  if (std::optional<std::string> error = session.configure(warning_flags, o.common)) {
    return usageError(*error);
  }
  if (o.syntax_only) return checkOnly(session, o.inputs);
  if (o.inputs.size() > 1) return usageError("one script at a time, unless -fsyntax-only");
  if (!o.depfile.empty() && o.output.empty()) return usageError("--depfile needs -o");
  const backends::Target* target = backends::findTarget(o.common.target);
  if (!target) {
    return usageError(
        fmt::format("unknown target `{}`; available: {}", o.common.target, targetNames()));
  }
  return emit(session, o, *target);
}

int runLint(const Args& raw_args) {
  Args args = raw_args;
  std::vector<std::string> warning_flags = takeWarningFlags(args);
  CLI::App app{"smachac lint: check scripts (parse and every pass) and write nothing"};
  CompileOptions o;
  app.add_option("inputs", o.inputs, "script files")->required()->type_name("SCRIPT");
  app.add_option("--target", o.common.target, "target whose naming rules apply");
  addCommonOptions(app, o.common);
  if (std::optional<int> code = parseArgs(app, args)) return *code;
  Session session;
  if (std::optional<std::string> error = session.configure(warning_flags, o.common)) {
    return usageError(*error);
  }
  return checkOnly(session, o.inputs);
}

}  // namespace smachac::driver
