// One walk over a meta block (MetaWalker) decides what is shown and in which order; a
// HelpWriter lays each part out, as terminal text or as markdown.
#include "backends/meta/template_help.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "backends/cpp/cpp_extensions.h"
#include "backends/cpp/cpp_target.h"
#include "backends/flexbe/flexbe_target.h"
#include "backends/smach/python_extensions.h"
#include "backends/smach/smach_target.h"
#include "backends/tmpl/values/value_convert.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::backends {
namespace {

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

/// The parts of a description. Depth 0 is a section heading; items start at depth 1.
class HelpWriter {
 public:
  virtual ~HelpWriter() = default;
  virtual void title(const std::string& name) = 0;
  virtual void field(std::string_view label, const std::string& value) = 0;
  virtual void heading(int depth, std::string_view label) = 0;
  virtual void item(int depth, const std::string& name) = 0;
  /// `{name: {description...}}`.
  virtual void variable(int depth, const std::string& name, bool optional,
                        const std::optional<std::string>& description) = 0;
  virtual void detail(int depth, std::string_view label, const std::string& value) = 0;
};

class MetaWalker {
 public:
  explicit MetaWalker(HelpWriter& out) : out_(out) {}

  void walk(const tmpl::Value& meta) {
    if (const tmpl::Value* name = field(meta, "name")) out_.title(text(*name));
    for (auto [key, label] : {std::pair{"description", "Description"},
                              {"language", "Language"},
                              {"framework", "Framework"},
                              {"type", "Type"}}) {
      if (const tmpl::Value* v = field(meta, key); v && !isEmpty(*v)) out_.field(label, text(*v));
    }
    names(meta, "includes", "Includes");
    names(meta, "extends", "Extends");
    entries(meta, "variables", "Variables");
    entries(meta, "input_keys", "Input Keys");
    entries(meta, "output_keys", "Output Keys");
    outcomes(meta);
  }

 private:
  /// A scalar or a list of scalars, one per line.
  void names(const tmpl::Value& meta, std::string_view key, std::string_view label) {
    const tmpl::Value* v = field(meta, key);
    if (!v || isEmpty(*v)) return;
    out_.heading(0, label);
    if (!v->isListOrTuple()) return out_.item(1, text(*v));
    for (const tmpl::Value& item : v->list().items()) out_.item(1, text(item));
  }

  void entries(const tmpl::Value& meta, std::string_view key, std::string_view label) {
    const tmpl::Value* v = field(meta, key);
    if (!v || isEmpty(*v) || !v->isListOrTuple()) return;
    out_.heading(0, label);
    for (const tmpl::Value& item : v->list().items()) entry(item, 1);
  }

  /// An entry of a variables / input_keys / output_keys list.
  void entry(const tmpl::Value& item, int depth) {
    if (item.isListOrTuple()) {
      const std::vector<tmpl::Value>& options = item.list().items();
      if (options.size() == 1) return variable(options.front(), depth, true);
      out_.heading(depth, "Option");
      for (const tmpl::Value& option : options) entry(option, depth + 1);
      return;
    }
    if (!item.isDict() || item.dict().size() != 1) return out_.item(depth, text(item));
    const tmpl::Value& body = item.dict().entries().front().second;
    if (!body.isListOrTuple()) return variable(item, depth, false);
    out_.heading(depth, text(item.dict().entries().front().first));
    for (const tmpl::Value& inner : body.list().items()) entry(inner, depth + 1);
  }

  /// `{name: {description, type, units, values}}`.
  void variable(const tmpl::Value& var, int depth, bool optional) {
    if (!var.isDict() || var.dict().size() != 1) return out_.item(depth, text(var));
    const auto& [name, info] = var.dict().entries().front();
    const tmpl::Value* description = field(info, "description");
    out_.variable(depth, text(name), optional,
                  description ? std::optional(text(*description)) : std::nullopt);
    for (auto [key, label] :
         {std::pair{"type", "Type"}, {"units", "Units"}, {"values", "Values"}}) {
      if (const tmpl::Value* v = field(info, key)) out_.detail(depth + 1, label, alternatives(*v));
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

  void outcomes(const tmpl::Value& meta) {
    const tmpl::Value* v = field(meta, "outcomes");
    if (!v || isEmpty(*v)) return;
    out_.heading(0, "Outcomes");
    if (!v->isListOrTuple()) return out_.item(1, text(*v));
    for (const tmpl::Value& outcome : v->list().items()) {
      if (outcome.isDict()) {
        variable(outcome, 1, false);
      } else {
        out_.item(1, text(outcome));
      }
    }
  }

  HelpWriter& out_;
};

/// Terminal text: four spaces a level, styles around headings, names and types.
class TextWriter final : public HelpWriter {
 public:
  explicit TextWriter(const HelpTextStyle& style) : style_(style) {}
  std::string take() { return std::move(out_); }

  void title(const std::string& name) override {
    out_ += style_.title + "Template: " + name + style_.reset + "\n";
  }
  void field(std::string_view label, const std::string& value) override {
    out_ += style_.heading + std::string(label) + ":" + style_.reset + " " + value + "\n";
  }
  void heading(int depth, std::string_view label) override {
    indent(depth);
    out_ += style_.heading + std::string(label) + ":" + style_.reset + "\n";
  }
  void item(int depth, const std::string& name) override {
    indent(depth);
    out_ += style_.name + name + style_.reset + "\n";
  }
  void variable(int depth, const std::string& name, bool optional,
                const std::optional<std::string>& description) override {
    indent(depth);
    out_ += style_.name + name + style_.reset + (optional ? " (optional)" : "");
    out_ += (description ? ": " + *description : "") + "\n";
  }
  void detail(int depth, std::string_view label, const std::string& value) override {
    indent(depth);
    out_ += std::string(label) + ": " + style_.type + value + style_.reset + "\n";
  }

 private:
  void indent(int depth) { out_.append(static_cast<size_t>(depth) * 4, ' '); }

  const HelpTextStyle& style_;
  std::string out_;
};

/// Markdown: a heading, fields as paragraphs, sections as bold labels over nested lists.
class MarkdownWriter final : public HelpWriter {
 public:
  std::string take() {
    while (!out_.empty() && out_.back() == '\n') out_.pop_back();
    return std::move(out_);
  }

  void title(const std::string& name) override { paragraph("### Template `" + name + "`"); }
  void field(std::string_view label, const std::string& value) override {
    paragraph("**" + std::string(label) + ":** " + value);
  }
  void heading(int depth, std::string_view label) override {
    if (depth == 0) return paragraph("**" + std::string(label) + ":**");
    bullet(depth, "*" + std::string(label) + ":*");
  }
  void item(int depth, const std::string& name) override { bullet(depth, markdownCode(name)); }
  void variable(int depth, const std::string& name, bool optional,
                const std::optional<std::string>& description) override {
    bullet(depth, markdownCode(name) + (optional ? " (optional)" : "") +
                      (description ? ": " + *description : ""));
  }
  void detail(int depth, std::string_view label, const std::string& value) override {
    bullet(depth, std::string(label) + ": " + markdownCode(value));
  }

 private:
  void paragraph(const std::string& line) {
    if (in_list_) out_ += "\n";
    in_list_ = false;
    out_ += line + "\n\n";
  }

  void bullet(int depth, const std::string& line) {
    out_.append(static_cast<size_t>(depth - 1) * 2, ' ');
    out_ += "- " + line + "\n";
    in_list_ = true;
  }

  std::string out_;
  bool in_list_ = false;
};

}  // namespace

generator::TemplatePath targetTemplatePath(const std::string& target,
                                           const std::vector<std::string>& template_dirs) {
  if (target == "cpp") return cpp::templatePath(template_dirs);
  if (target == "flexbe") return flexbe::templatePath(template_dirs);
  return smach::templatePath(template_dirs);
}

std::unique_ptr<tmpl::Environment> targetEnvironment(const std::string& target,
                                                     const generator::TemplatePath& path,
                                                     const generator::ValueConverter& converter) {
  auto env = std::make_unique<tmpl::Environment>(path.dirs, path.builtin_sets, path.builtins);
  if (target == "cpp") {
    cpp::registerCppExtensions(*env, converter, false);
  } else {
    smach::registerPythonExtensions(*env, converter, false);
  }
  return env;
}

tmpl::Value templateMeta(tmpl::Environment& env, const std::string& resolved) {
  std::optional<std::string> meta = env.metaBlock(resolved);
  tmpl::Value parsed = meta ? tmpl::parseYaml(*meta, resolved + " (meta block)") : tmpl::Value();
  if (!parsed.isDict()) {
    throw tmpl::TemplateError(resolved, 0, 0,
                              "template `" + resolved + "` has no meta block to describe it");
  }
  return parsed;
}

std::string templateHelpText(const tmpl::Value& meta, const HelpTextStyle& style) {
  TextWriter writer(style);
  MetaWalker(writer).walk(meta);
  return writer.take();
}

std::string markdownCode(std::string_view text) {
  size_t longest = 0;
  size_t run = 0;
  for (char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  std::string fence(longest + 1, '`');
  std::string pad = longest > 0 ? " " : "";
  return fence + pad + std::string(text) + pad + fence;
}

std::string templateHelpMarkdown(const tmpl::Value& meta) {
  MarkdownWriter writer;
  MetaWalker(writer).walk(meta);
  return writer.take();
}

}  // namespace smachac::backends
