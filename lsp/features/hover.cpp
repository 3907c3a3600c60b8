// textDocument/hover: markdown about the name under the position, with its range.
//   * a template: its documentation, as `smachac help` gives it (backends/meta/template_help.h);
//   * a state: what it is, its template, its outcomes (its template's when it declares
//     none) and the sub-script it comes from;
//   * a userdata key: its type in its scope (passes/analysis/key_types.h), its value when a
//     `userdata` entry sets it (the last one in the scope, as SMACH sees it), and what sets
//     it; a state's own remapped name shows the parent's key it stands for;
//   * a param (a lookup or a `params` entry): its value as the state sees it (the params
//     after inheritance, as the frontend resolved the lookup) and the `params` that set it;
//   * an outcome: whose it is; a sub-script: its file.
// Nothing there, or a template without documentation: null.
#include <algorithm>
#include <filesystem>
#include <optional>

#include "backends/meta/template_help.h"
#include "ir/type.h"
#include "ir/value_text.h"
#include "lsp/features/definition.h"
#include "lsp/features/features.h"
#include "lsp/index_templates.h"
#include "lsp/script_index.h"
#include "passes/analysis/key_types.h"
#include "passes/analysis/userdata_scope.h"

namespace smachac::lsp {
namespace {

using ir::StateId;

std::string code(std::string_view text) { return backends::markdownCode(text); }

std::string stateLabel(const ir::Module& module, StateId id) {
  return id == module.root() ? "the script" : code(module.state(id).name.text);
}

/// The path of a file of the analysis from the document's directory.
std::string relativePath(const Analysis& analysis, uint32_t file) {
  namespace fs = std::filesystem;
  fs::path base = fs::path(analysis.sources.path(analysis.file)).parent_path();
  fs::path path = fs::path(analysis.sources.path(file)).lexically_normal();
  fs::path relative = path.lexically_relative(base.empty() ? fs::path(".") : base);
  return (relative.empty() ? path : relative).string();
}

/// "line N", after the file's path when it is another file.
std::string lineOf(const Analysis& analysis, const SourceLoc& loc) {
  std::string line = "line " + std::to_string(loc.line);
  return loc.file == analysis.file ? line : relativePath(analysis, loc.file) + " " + line;
}

std::string names(const std::vector<std::string>& list) {
  std::string out;
  for (const std::string& name : list) out += (out.empty() ? "" : ", ") + code(name);
  return out;
}

std::string kindWord(ir::StateKind kind) {
  switch (kind) {
    case ir::StateKind::Base:
      return "script";
    case ir::StateKind::StateMachine:
      return "state machine";
    case ir::StateKind::Concurrence:
      return "concurrence";
    case ir::StateKind::Leaf:
      return "state";
  }
  return "state";
}

std::string stateHover(const Workspace& workspace, const ir::State& s) {
  std::string text = "**" + kindWord(s.kind) + "** " + code(s.name.text);
  if (s.template_name) text += ": template " + code(s.template_name->text);
  std::vector<std::string> outcomes;
  for (const ir::Name& outcome : s.outcomes) outcomes.push_back(outcome.text);
  if (!outcomes.empty()) {
    text += "\n\nOutcomes: " + names(outcomes);
  } else if (s.template_name) {
    outcomes = TemplateFinder(workspace.settings()).outcomes(s.template_name->text);
    if (!outcomes.empty()) text += "\n\nOutcomes (from its template): " + names(outcomes);
  }
  if (!s.included_from.empty()) {
    text += "\n\nIncluded from the sub-script " + code(s.included_from.back().script.text);
  }
  return text;
}

/// What a definition of a key or param is, and where.
std::string sourceLine(const ScriptIndex& index, const Occurrence& definition) {
  const ir::Module& module = *index.analysis().module;
  std::string what = definition.site == Site::Userdata ? "`userdata`"
                     : definition.site == Site::Params ? "`params`"
                                                       : "output";
  return "- " + what + " of " + stateLabel(module, definition.holder) + " (" +
         lineOf(index.analysis(), definition.loc) + ")";
}

std::string sources(const ScriptIndex& index, uint32_t symbol, const char* none) {
  std::vector<const Occurrence*> definitions = index.definitions(symbol);
  if (definitions.empty()) return std::string("\n\n") + none;
  std::string text = "\n\nSet by:";
  for (const Occurrence* definition : definitions) text += "\n" + sourceLine(index, *definition);
  return text;
}

/// The scope and name a state's own remapped name stands for, or the key itself.
std::pair<StateId, std::string> scopeKey(const ir::Module& module, const Occurrence& at,
                                         const std::string& key) {
  const ir::State& scope = module.state(at.scope);
  if (ir::isContainer(scope.kind) || !scope.parent.valid()) return {at.scope, key};
  for (const ir::Remap& remap : scope.remapping) {
    if (remap.key.text == key) return {scope.parent, remap.parent_key.text};
  }
  return {scope.parent, key};
}

/// The value of the last `userdata` entry for `key` in the scope of `container`.
const ir::Value* lastLiteral(const ir::Module& module, StateId container, const std::string& key) {
  passes::UserdataScope scope(module, container);
  const ir::Value* value = nullptr;
  for (const passes::LiteralDef& literal : scope.literals()) {
    if (literal.arg->key.text == key) value = &literal.arg->value;
  }
  return value;
}

/// The literal `key` has when `container` starts: its scope's `userdata` entry, or for an
/// input key without one, the literal of the parent's key it is copied from.
const ir::Value* literalOf(const ir::Module& module, StateId container, std::string key) {
  while (container.valid() && ir::isContainer(module.state(container).kind)) {
    if (const ir::Value* value = lastLiteral(module, container, key)) return value;
    const ir::State& c = module.state(container);
    auto input = std::find_if(c.input_keys.begin(), c.input_keys.end(),
                              [&](const ir::Name& name) { return name.text == key; });
    if (input == c.input_keys.end()) return nullptr;
    key = passes::remappedName(c, *input).text;
    container = c.parent;
  }
  return nullptr;
}

std::string keyHover(const ScriptIndex& index, const Occurrence& at) {
  const ir::Module& module = *index.analysis().module;
  const std::string& name = index.symbol(at.symbol).name;
  auto [scope, key] = scopeKey(module, at, name);
  std::string text = "**userdata** " + code(name);
  if (key != name) text += " (remapped to " + code(key) + ")";
  passes::KeyTypes types(module);
  if (std::optional<ir::Type> type = types.find(scope, key)) text += ": " + code(type->str());
  if (const ir::Value* value = literalOf(module, scope, key)) {
    text += " = " + code(ir::formatValue(*value));
  }
  return text + sources(index, at.symbol, "Nothing in the script sets it.");
}

std::string paramHover(const ScriptIndex& index, const Occurrence& at) {
  const ir::Module& module = *index.analysis().module;
  const std::string& name = index.symbol(at.symbol).name;
  std::string text = "**param** " + code(name);
  const ir::Boxed<ir::Value>& params = module.state(at.holder).params;
  if (const ir::Value* value = params ? params->find(name) : nullptr) {
    text += ": " + code(ir::Type::ofValue(*value).str()) + " = " + code(ir::formatValue(*value));
  }
  return text + sources(index, at.symbol, "No `params` sets it.");
}

std::optional<std::string> hoverText(const Workspace& workspace, const ScriptIndex& index,
                                     const Occurrence& at) {
  const ir::Module& module = *index.analysis().module;
  const Symbol& symbol = index.symbol(at.symbol);
  switch (symbol.kind) {
    case SymbolKind::Template:
      return TemplateFinder(workspace.settings()).documentation(symbol.name);
    case SymbolKind::State:
      return stateHover(workspace, module.state(at.scope));
    case SymbolKind::UserdataKey:
      return keyHover(index, at);
    case SymbolKind::Param:
      return paramHover(index, at);
    case SymbolKind::Outcome:
      return "**outcome** " + code(symbol.name) + " of " + stateLabel(module, at.scope);
    case SymbolKind::SubScript:
      return "**sub-script** " + code(symbol.name) + ": " +
             code(relativePath(index.analysis(), symbol.file));
  }
  return std::nullopt;
}

}  // namespace

Json hover(Workspace& workspace, const Json& params) {
  PointedAt at = pointedAt(workspace, params);
  if (!at.occurrence) return nullptr;
  std::optional<std::string> text = hoverText(workspace, *at.index, *at.occurrence);
  if (!text) return nullptr;
  return {{"contents", {{"kind", "markdown"}, {"value", *text}}},
          {"range", toJson(at.index->analysis().lines().rangeOf(at.occurrence->loc))}};
}

}  // namespace smachac::lsp
