// `smachac [-target=T] script.yml [-o out]` and `-fsyntax-only`: compile scripts to a target.
// (`smachac lint` is lint_command.cpp.)
#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <utility>
#include <variant>

#include "backends/targets.h"
#include "ir/support/version.h"
#include "tools/smachac/args.h"
#include "tools/smachac/compile_options.h"
#include "tools/smachac/depfile.h"
#include "tools/smachac/library_output.h"
#include "tools/smachac/output.h"
#include "tools/smachac/process_exit.h"
#include "tools/smachac/quick_args.h"
#include "tools/smachac/script_inputs.h"
#include "tools/smachac/session.h"
#include "tools/smachac/warning_help.h"

namespace smachac::driver {
namespace {

std::string targetNames() {
  std::string names;
  for (const backends::Target& t : backends::targets()) {
    names += (names.empty() ? "" : ", ") + std::string(t.name);
  }
  return names;
}

/// The subcommands' words, from commands.def.
std::string subcommandNames() {
  std::string names;
#define SMACHAC_COMMAND(word, function, help) \
  names += (names.empty() ? "" : ", ") + std::string(word);
#include "tools/smachac/commands.def"
  return names;
}

/// What `--version` prints (CLI11 adds the line break).
std::string versionText() { return fmt::format("smachac {}", kVersion); }

void setUp(CLI::App& app, CompileOptions& o) {
  app.name("smachac");
  app.description("smachac: a compiler for SMACHA state-machine scripts.\nSubcommands: " +
                  subcommandNames() + " (run `smachac <subcommand> --help`).");
  app.set_version_flag("--version", versionText());
  addScriptInputs(app, o.scripts);
  app.add_option("--target", o.common.target, "output target: " + targetNames());
  app.add_option("-o,--output", o.output, "output file (default: standard output)");
  app.add_option("--emit", o.emit,
                 "C++ target: `program` (one file with main(), the default) or `library` (a "
                 "header/source pair: -o DIR/ or -o DIR/NAME.cpp)")
      ->type_name("KIND");
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

/// The -emit check: the C++ target emits a `program` or a `library`; others take no -emit.
std::optional<std::string> emitProblem(const std::string& emit, const backends::Target& target) {
  if (emit.empty()) return std::nullopt;
  if (target.name != "cpp") {
    return fmt::format("-emit={} applies to -target=cpp only (the target is `{}`)", emit,
                       target.name);
  }
  if (emit != "program" && emit != "library") {
    return fmt::format("unknown -emit kind `{}`; available: program, library", emit);
  }
  return std::nullopt;
}

/// `dir/name` ("." when `dir` is empty; no doubled `/`).
std::string inDirectory(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir.empty() ? "." : dir) / name).string();
}

/// Where generated files go: the -o directory (multi-file targets, -emit=library), the -o
/// file, or stdout.
std::string outputPath(const CompileOptions& o, const std::string& dir,
                       const backends::OutputFile& file) {
  if (!file.name.empty()) return inDirectory(dir, file.name);
  return o.output.empty() ? "-" : o.output;
}

/// Writes the files; their contents are moved out (a big script's code is not copied).
int writeOutputs(const CompileOptions& o, const std::string& dir,
                 std::vector<backends::OutputFile>& files) {
  std::vector<std::pair<std::string, std::string>> contents;
  for (backends::OutputFile& file : files) {
    std::string path = outputPath(o, dir, file);
    if (path == "-") {
      writeFileAtomically(path, file.content);
    } else {
      contents.emplace_back(std::move(path), std::move(file.content));
    }
  }
  std::optional<std::string> error = writeFilesAtomically(contents);
  if (!error) return kExitOk;
  std::cerr << "smachac: error: " << *error << "\n";
  return kExitUsageError;
}

int emit(Session& session, const CompileOptions& o, const backends::Target& target,
         const std::optional<LibraryOutput>& library) {
  std::optional<ir::Module> module = session.compile(o.scripts.inputs.front());
  std::optional<std::vector<backends::OutputFile>> files;
  backends::EmitOptions emit_options{.template_dirs = o.common.template_dirs,
                                     .comments = o.comments,
                                     .introspection = o.introspection,
                                     .flexbe_ros = o.flexbe_ros,
                                     .output = o.output,
                                     .library = std::nullopt};
  std::string depfile;
  if (module) {
    std::string depfile_target = o.output;
    if (library) {
      emit_options.library = libraryNames(*library, module->state(module->root()).name.text);
      depfile_target = inDirectory(library->dir, emit_options.library->source);
    }
    // Read before the target takes the module (it may free the IR before its last render).
    if (!o.depfile.empty()) {
      depfile = depfileText(depfile_target, *module, session.sources(), o.common.template_dirs);
    }
    backends::EmitContext context{session.sources(), session.diags(), emit_options};
    files = target.emit(std::move(*module), context);
  }
  session.printDiagnostics();
  if (!files || session.diags().hasErrors()) return session.failureExitCode();
  if (!o.depfile.empty()) {
    if (std::optional<std::string> error = writeFileAtomically(o.depfile, depfile)) {
      std::cerr << "smachac: error: " << *error << "\n";
      return kExitUsageError;
    }
  }
  return writeOutputs(o, library ? library->dir : o.output, *files);
}

/// -emit=library: where the pair goes, or a usage error's exit code.
std::variant<std::optional<LibraryOutput>, int> libraryOutputOf(const CompileOptions& o) {
  if (o.emit != "library") return std::optional<LibraryOutput>();
  std::variant<LibraryOutput, std::string> output = libraryOutput(o.output);
  if (const std::string* error = std::get_if<std::string>(&output)) return usageError(*error);
  return std::optional<LibraryOutput>(std::get<LibraryOutput>(output));
}

}  // namespace

int runCompile(const Args& raw_args) {
  // `--version` alone (what build scripts ask) prints what CLI11 would, without setting it up
  // (0.3 M of the 0.5 M instructions the process ran).
  if (raw_args.size() == 1 && raw_args.front() == "--version") {
    std::cout << versionText() << '\n';
    return kExitOk;
  }
  Args args = raw_args;
  std::vector<std::string> warning_flags = takeWarningFlags(args);
  std::optional<CompileOptions> quick = readQuickCompileLine(args);
  CompileOptions o = quick ? std::move(*quick) : CompileOptions();
  if (!quick) {
    CLI::App app;
    setUp(app, o);
    if (std::optional<int> code = parseArgs(app, args)) return *code;
  }
  if (o.common.list_passes) return printPassList(), kExitOk;
  if (o.scripts.list_warnings) return printWarningList(), kExitOk;
  if (o.list_targets) {
    for (const backends::Target& t : backends::targets()) {
      std::cout << fmt::format("{:<10} {}\n", t.name, t.description);
    }
    return kExitOk;
  }
  if (o.scripts.inputs.empty()) return usageError("no input script (see `smachac --help`)");
  o.common.sub_script_alone = o.syntax_only;
  leaveMemoryToProcessExit();
  Session session;
  if (std::optional<std::string> error = session.configure(warning_flags, o.common)) {
    return usageError(*error);
  }
  if (o.syntax_only) return checkScripts(session, o.scripts.inputs);
  if (o.scripts.inputs.size() > 1) return usageError("one script at a time, unless -fsyntax-only");
  if (!o.depfile.empty() && o.output.empty()) return usageError("--depfile needs -o");
  if (!o.depfile.empty() && o.scripts.inputs.front() == kStandardInputPath) {
    return usageError("--depfile needs a script file, not standard input");
  }
  const backends::Target* target = backends::findTarget(o.common.target);
  if (!target) {
    return usageError(
        fmt::format("unknown target `{}`; available: {}", o.common.target, targetNames()));
  }
  if (std::optional<std::string> problem = emitProblem(o.emit, *target)) {
    return usageError(*problem);
  }
  std::variant<std::optional<LibraryOutput>, int> library = libraryOutputOf(o);
  if (const int* code = std::get_if<int>(&library)) return *code;
  return emit(session, o, *target, std::get<std::optional<LibraryOutput>>(library));
}

}  // namespace smachac::driver
