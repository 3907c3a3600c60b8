// `smachac help [TEMPLATE] [--target=smach|cpp|flexbe] [-I dir]... [--ansi|--no-ansi]`: without
// a template, lists the templates of each target (or of --target) with a one-line summary;
// with one, prints its meta block readably, as SMACHA's help does (backends/meta/template_help.h
// lays it out).
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <iostream>
#include <optional>
#include <string>

#include "backends/meta/template_help.h"
#include "backends/tmpl/environment.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/diagnostic_printer.h"
#include "tools/smachac/commands.h"
#include "tools/smachac/help_style.h"
#include "tools/smachac/template_list.h"

namespace smachac::driver {
namespace {

struct HelpOptions {
  std::string template_name;
  std::string target;  ///< "" (every target when listing, smach for one template)
  std::vector<std::string> template_dirs;
  bool ansi = false;
  bool no_ansi = false;

  /// Colours on a terminal, or when asked; never with --no-ansi.
  bool colours() const { return !no_ansi && (ansi || isatty(STDOUT_FILENO) != 0); }
};

std::optional<int> parse(HelpOptions& o, const Args& args) {
  CLI::App app{"smachac help: describe a template from its meta block", "smachac help"};
  app.add_option("template", o.template_name,
                 "template name (Foo) or file name (Foo.tpl.py); without one, list the templates")
      ->type_name("TEMPLATE");
  app.add_option("--target", o.target, "the target whose templates to describe (default smach)")
      ->check(CLI::IsMember({"smach", "cpp", "flexbe"}));
  app.add_option("-I,--template-dir", o.template_dirs,
                 "template search directory, before the built-ins (repeatable)")
      ->allow_extra_args(false);
  app.add_flag("--ansi", o.ansi, "colours even when the output is not a terminal");
  app.add_flag("-n,--no-ansi", o.no_ansi, "plain text, without colours");
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsageError;
  }
  return std::nullopt;
}

int fail(DiagnosticEmitter& diags, const SourceManager& sources) {
  printDiagnostics(std::cerr, diags.diagnostics(), sources, DiagnosticFormat::Text);
  return kExitInputError;
}

}  // namespace

int runHelp(const Args& args) {
  HelpOptions o;
  if (std::optional<int> code = parse(o, args)) return *code;
  if (o.template_name.empty()) {
    const std::vector<std::string> every = {"smach", "cpp", "flexbe"};
    for (const std::string& target : o.target.empty() ? every : std::vector{o.target}) {
      listTemplates(std::cout, target, o.template_dirs, HelpStyle(o.colours()));
    }
    return kExitOk;
  }
  generator::TemplatePath path = backends::targetTemplatePath(o.target, o.template_dirs);
  generator::ValueConverter converter;
  std::unique_ptr<tmpl::Environment> env_owner =
      backends::targetEnvironment(o.target, path, converter);
  tmpl::Environment& env = *env_owner;
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<std::string> name = env.resolveScriptTemplate(o.template_name);
  if (!name) {
    diags.emit<DiagKind::UnknownTemplate>(SourceLoc{}, o.template_name,
                                          generator::describePath(path),
                                          generator::suggestTemplate(o.template_name, path));
    return fail(diags, sources);
  }
  try {
    HelpStyle style(o.colours());
    std::cout << backends::templateHelpText(
        backends::templateMeta(env, *name),
        {style.title, style.heading, style.name, style.type, style.reset});
  } catch (const tmpl::TemplateError& e) {
    generator::TemplateFiles files(sources, path.builtins);
    diags.emit<DiagKind::TemplateError>(files.locate(e), ForeignMessage(e.message()));
    return fail(diags, sources);
  }
  return kExitOk;
}

}  // namespace smachac::driver
