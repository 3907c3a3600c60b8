// `smachac help [TEMPLATE] [--target=smach|cpp|flexbe] [-I dir]... [--ansi|--no-ansi]`: without
// a template, lists the templates of each target (or of --target) with a one-line summary;
// with one, prints its meta block readably, as SMACHA's help does: name, description,
// language, framework, type,
// includes, extends, then variables, input keys, output keys and outcomes. In the lists, a
// `{name: {description, type, units, values}}` entry is required, a one-entry list around it
// optional, a longer list a choice of alternatives, and `{heading: [...]}` a group.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <iostream>
#include <optional>
#include <string>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/value_convert.h"
#include "backends/tmpl/value_print.h"
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

std::string text(const tmpl::Value& v) {
  std::string s = tmpl::str(v);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

const tmpl::Value* field(const tmpl::Value& map, std::string_view key) {
  if (!map.isDict()) return nullptr;
  const tmpl::Value* v = map.dict().findString(key);
  return v && !v->isNone() && !v->isUndefined() ? v : nullptr;
}

bool isEmpty(const tmpl::Value& v) {
  return v.isNone() || (v.isListOrTuple() && v.list().items().empty()) ||
         (v.isDict() && v.dict().empty()) || (v.isString() && v.s().empty());
}

class MetaPrinter {
 public:
  MetaPrinter(std::ostream& out, bool ansi) : out_(out), style_(ansi) {}

  void print(const tmpl::Value& meta) {
    if (const tmpl::Value* name = field(meta, "name")) {
      out_ << style_.title << "Template: " << text(*name) << style_.reset << "\n";
    }
    for (auto [key, label] : {std::pair{"description", "Description"},
                              {"language", "Language"},
                              {"framework", "Framework"},
                              {"type", "Type"}}) {
      if (const tmpl::Value* v = field(meta, key); v && !isEmpty(*v)) {
        out_ << style_.heading << label << ":" << style_.reset << " " << text(*v) << "\n";
      }
    }
    printNames(meta, "includes", "Includes");
    printNames(meta, "extends", "Extends");
    printEntries(meta, "variables", "Variables");
    printEntries(meta, "input_keys", "Input Keys");
    printEntries(meta, "output_keys", "Output Keys");
    printOutcomes(meta);
  }

 private:
  void indent(int depth) {
    for (int i = 0; i < depth; ++i) out_ << "    ";
  }

  /// A scalar or a list of scalars, one per line.
  void printNames(const tmpl::Value& meta, std::string_view key, std::string_view label) {
    const tmpl::Value* v = field(meta, key);
    if (!v || isEmpty(*v)) return;
    out_ << style_.heading << label << ":" << style_.reset << "\n";
    if (!v->isListOrTuple()) return line(1, text(*v));
    for (const tmpl::Value& item : v->list().items()) line(1, text(item));
  }

  void line(int depth, const std::string& s) {
    indent(depth);
    out_ << style_.name << s << style_.reset << "\n";
  }

  void printEntries(const tmpl::Value& meta, std::string_view key, std::string_view label) {
    const tmpl::Value* v = field(meta, key);
    if (!v || isEmpty(*v) || !v->isListOrTuple()) return;
    out_ << style_.heading << label << ":" << style_.reset << "\n";
    for (const tmpl::Value& entry : v->list().items()) printEntry(entry, 1);
  }

  /// An entry of a variables / input_keys / output_keys list.
  void printEntry(const tmpl::Value& entry, int depth) {
    if (entry.isListOrTuple()) {
      const std::vector<tmpl::Value>& options = entry.list().items();
      if (options.size() == 1) return printVariable(options.front(), depth, true);
      indent(depth);
      out_ << style_.heading << "Option:" << style_.reset << "\n";
      for (const tmpl::Value& option : options) printEntry(option, depth + 1);
      return;
    }
    if (!entry.isDict() || entry.dict().size() != 1) return line(depth, text(entry));
    const tmpl::Value& body = entry.dict().entries().front().second;
    if (!body.isListOrTuple()) return printVariable(entry, depth, false);
    indent(depth);
    out_ << style_.heading << text(entry.dict().entries().front().first) << ":" << style_.reset
         << "\n";
    for (const tmpl::Value& item : body.list().items()) printEntry(item, depth + 1);
  }

  /// `{name: {description, type, units, values}}`.
  void printVariable(const tmpl::Value& var, int depth, bool optional) {
    if (!var.isDict() || var.dict().size() != 1) return line(depth, text(var));
    const auto& [name, info] = var.dict().entries().front();
    indent(depth);
    out_ << style_.name << text(name) << style_.reset << (optional ? " (optional)" : "");
    const tmpl::Value* description = field(info, "description");
    out_ << (description ? ": " + text(*description) : "") << "\n";
    for (auto [key, label] :
         {std::pair{"type", "Type"}, {"units", "Units"}, {"values", "Values"}}) {
      const tmpl::Value* v = field(info, key);
      if (!v) continue;
      indent(depth + 1);
      out_ << label << ": " << style_.type << alternatives(*v) << style_.reset << "\n";
    }
  }

  static std::string alternatives(const tmpl::Value& v) {
    if (!v.isListOrTuple()) return text(v);
    std::string out;
    for (const tmpl::Value& item : v.list().items()) {
      out += (out.empty() ? "" : " or ") + text(item);
    }
    return out;
  }

  void printOutcomes(const tmpl::Value& meta) {
    const tmpl::Value* v = field(meta, "outcomes");
    if (!v || isEmpty(*v)) return;
    out_ << style_.heading << "Outcomes:" << style_.reset << "\n";
    if (!v->isListOrTuple()) return line(1, text(*v));
    for (const tmpl::Value& outcome : v->list().items()) {
      if (outcome.isDict()) {
        printVariable(outcome, 1, false);
      } else {
        line(1, text(outcome));
      }
    }
  }

  std::ostream& out_;
  HelpStyle style_;
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
  generator::TemplatePath path = targetTemplatePath(o.target, o.template_dirs);
  generator::ValueConverter converter;
  std::unique_ptr<tmpl::Environment> env_owner = targetEnvironment(o.target, path, converter);
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
    std::optional<std::string> meta = env.metaBlock(*name);
    tmpl::Value parsed = meta ? tmpl::parseYaml(*meta, *name + " (meta block)") : tmpl::Value();
    if (!parsed.isDict()) {
      throw tmpl::TemplateError(*name, 0, 0,
                                "template `" + *name + "` has no meta block to describe it");
    }
    MetaPrinter(std::cout, o.colours()).print(parsed);
  } catch (const tmpl::TemplateError& e) {
    generator::TemplateFiles files(sources, path.builtins);
    diags.emit<DiagKind::TemplateError>(files.locate(e), e.message());
    return fail(diags, sources);
  }
  return kExitOk;
}

}  // namespace smachac::driver
