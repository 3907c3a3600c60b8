// Shared driver plumbing: options, diagnostics and the compile pipeline of one script.
#include "tools/smachac/session.h"

#include <fmt/core.h>

#include <iostream>
#include <iterator>

#include "checker/check_script.h"
#include "frontend/yaml_loader.h"
#include "ir/printer.h"
#include "passes/pipeline.h"
#include "tools/smachac/huge_pages.h"

namespace smachac::driver {
namespace {

/// The script on standard input, or nullopt (reported) when it is larger than a script may be.
std::optional<std::string> readStandardInput(DiagnosticEmitter& diags) {
  std::string text;
  std::istreambuf_iterator<char> in(std::cin), end;
  while (in != end && text.size() <= frontend::kMaxScriptBytes) text += *in++;
  if (text.size() <= frontend::kMaxScriptBytes) return text;
  diags.emit<DiagKind::FileTooLarge>(SourceLoc{}, kStandardInputName,
                                     fmt::format("more than {}", frontend::kMaxScriptBytes),
                                     frontend::kMaxScriptBytes);
  return std::nullopt;
}

}  // namespace

void addSearchDirectories(CLI::App& app, std::vector<std::string>& template_dirs,
                          std::vector<std::string>& script_dirs) {
  app.add_option("-I,--template-dir", template_dirs,
                 "template search directory, before the built-ins (repeatable)")
      ->allow_extra_args(false);
  app.add_option("-S,--script-dir", script_dirs,
                 "sub-script search directory, after the including file's (repeatable)")
      ->allow_extra_args(false);
}

void addCommonOptions(CLI::App& app, CommonOptions& o) {
  addSearchDirectories(app, o.template_dirs, o.script_dirs);
  app.add_option("--fdiagnostics-format", o.diagnostics_format,
                 "diagnostics as text, json or sarif")
      ->check(CLI::IsMember({"text", "json", "sarif"}));
  app.add_option("--disable-pass", o.disabled_passes, "do not run this pass (repeatable)")
      ->allow_extra_args(false);
  app.add_option("--print-ir-after", o.print_ir_after,
                 "print the IR to stderr after this pass (or `all`)");
  app.add_flag("--list-passes", o.list_passes, "list the passes and exit");
  app.add_flag("-O,--optimize", o.optimize,
               "run the optimisation passes (prune, fold, de-duplicate) after the checks");
}

std::optional<std::string> Session::configure(const std::vector<std::string>& warning_flags,
                                              const CommonOptions& options) {
  options_ = options;
  WarningOptions warnings;
  for (const std::string& flag : warning_flags) {
    if (std::optional<std::string> error = warnings.apply(flag)) return error;
  }
  diags_ = std::make_unique<DiagnosticEmitter>(std::move(warnings));
  format_ = *parseDiagnosticFormat(options.diagnostics_format);
  for (const std::string& name : options.disabled_passes) {
    if (!passes::findPass(name)) return fmt::format("unknown pass `{}` in -disable-pass", name);
  }
  const std::string& after = options.print_ir_after;
  if (!after.empty() && after != "all" && !passes::findPass(after)) {
    return fmt::format("unknown pass `{}` in -print-ir-after", after);
  }
  return std::nullopt;
}

std::optional<ir::Module> Session::compile(const std::string& path) {
  checker::CheckOptions check;
  check.target = options_.target;
  check.template_dirs = options_.template_dirs;
  check.script_dirs = options_.script_dirs;
  check.disabled_passes.insert(options_.disabled_passes.begin(), options_.disabled_passes.end());
  check.print_ir_after = options_.print_ir_after;
  check.print_ir = [this](std::string_view pass, const ir::Module& m) {
    std::cerr << "; IR after " << pass << "\n" << ir::printModule(m, sources_);
  };
  check.optimize = options_.optimize;
  check.sub_script_alone = options_.sub_script_alone;
  if (path != kStandardInputPath) {
    preferHugePagesFor(path);
    return checker::checkScript(path, std::nullopt, check, sources_, *diags_).module;
  }
  std::optional<std::string> text = readStandardInput(*diags_);
  if (!text) return std::nullopt;
  return checker::checkScript(std::string(kStandardInputName), std::move(text), check, sources_,
                              *diags_)
      .module;
}

void Session::printDiagnostics() const {
  std::cerr.flush();
  smachac::printDiagnostics(std::cerr, diags_->diagnostics(), sources_, format_);
}

int Session::failureExitCode() const {
  for (const Diagnostic& d : diags_->diagnostics()) {
    if (d.severity == Severity::Error && isIoError(d.kind)) return kExitUsageError;
  }
  return kExitInputError;
}

std::optional<int> parseArgs(CLI::App& app, const Args& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsageError;
  }
  return std::nullopt;
}

int usageError(const std::string& message) {
  std::cerr << "smachac: error: " << message << "\n";
  return kExitUsageError;
}

void printPassList() {
  for (const passes::PassInfo& pass : passes::passTable()) {
    std::cout << fmt::format("{:<28} {:<9} {}\n", pass.name,
                             pass.kind == passes::PassKind::Check ? "check" : "transform",
                             pass.description);
  }
}

}  // namespace smachac::driver
