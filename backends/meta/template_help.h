// A template's documentation from its meta block, as `smachac help TEMPLATE` prints it on a
// terminal and as the language server shows it on hover (markdown). Both tell the same
// things in the same order: name, description, language, framework, type, includes,
// extends, then variables, input keys, output keys and outcomes. In the lists, a
// `{name: {description, type, units, values}}` entry is required, a one-entry list around it
// optional, a longer list a choice of alternatives ("Option:"), and `{heading: [...]}` a
// group. Also where a target's templates are found, as help and the server look them up.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value.h"

namespace smachac::backends {

/// The search path of `target` (smach, cpp or flexbe; any other name reads as smach) with
/// the -I directories first.
generator::TemplatePath targetTemplatePath(const std::string& target,
                                           const std::vector<std::string>& template_dirs);

/// An environment for reading `target`'s templates (its filters registered); `converter`
/// must outlive it.
std::unique_ptr<tmpl::Environment> targetEnvironment(const std::string& target,
                                                     const generator::TemplatePath& path,
                                                     const generator::ValueConverter& converter);

/// The parsed meta block of the template file `resolved` (a name resolveScriptTemplate
/// gave). Throws tmpl::TemplateError when the block does not parse or there is none.
tmpl::Value templateMeta(tmpl::Environment& env, const std::string& resolved);

/// The escape sequences of the terminal text's parts; all empty for plain text.
struct HelpTextStyle {
  std::string title, heading, name, type, reset;
};

/// The description of a parsed meta block as `smachac help` prints it, one item a line.
std::string templateHelpText(const tmpl::Value& meta, const HelpTextStyle& style);

/// The same description in markdown: fields as paragraphs, lists as nested bullet lists,
/// names and types as code. No trailing newline.
std::string templateHelpMarkdown(const tmpl::Value& meta);

/// `text` as a markdown code span, fenced by more backticks than it holds in a row.
std::string markdownCode(std::string_view text);

}  // namespace smachac::backends
