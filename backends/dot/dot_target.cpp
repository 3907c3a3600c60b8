// The dot target: view model + one template.
#include "backends/dot/dot_target.h"

#include <fmt/core.h>

#include "backends/dot/dot_view.h"
#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value_print.h"
#include "templates/builtin_templates.h"

namespace smachac::backends::dot {
namespace {

/// A DOT double-quoted string: quotes and backslashes escaped, line breaks as \n (a line break
/// in the label), other control characters shown as the text `\xNN` (Graphviz rejects some).
std::string dotString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += fmt::format("\\\\x{:02x}", byte);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::optional<std::vector<OutputFile>> emitDot(ir::Module&& module, EmitContext& context) {
  tmpl::Environment env(context.options.template_dirs, {"dot/"}, templates::builtinTemplates());
  env.addFilter("dotstr", [](const tmpl::Value& input, const tmpl::CallArgs&) {
    return tmpl::Value::string(dotString(tmpl::str(input)));
  });
  tmpl::Value graph = graphView(module, context.diags.diagnostics());
  tmpl::Value vars = tmpl::Value::newDict();
  vars.dict().setString("graph", graph);
  try {
    std::string text = env.render("Graph.tpl.dot", vars);
    return std::vector<OutputFile>{{"", text + "\n"}};
  } catch (const tmpl::TemplateError& e) {
    context.diags.emit<DiagKind::TemplateError>(SourceLoc{}, ForeignMessage(e.what()));
    return std::nullopt;
  }
}

}  // namespace smachac::backends::dot
