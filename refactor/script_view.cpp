// Loading a script for the tools, and finding its root states and keys.
#include "refactor/script_view.h"

#include <array>

#include "frontend/shorthand.h"
#include "frontend/yaml_loader.h"
#include "ir/support/check.h"

namespace smachac::refactor {
namespace {

/// The shorthand spellings the tools write; their longhands come from the frontend.
constexpr std::array<std::string_view, 13> kWrittenShorthands = {
    "T", "S", "o", "s", "p", "ud", "ik", "ok", "r", "t", "do", "om", "cb"};

std::string_view canonicalKey(std::string_view key) {
  return frontend::longhandOf(key).value_or(key);
}

}  // namespace

std::optional<ScriptView> ScriptView::load(const std::string& path,
                                           const frontend::FrontendOptions& options,
                                           SourceManager& sources, DiagnosticEmitter& diags) {
  return fromLowered(frontend::lowerScript(path, options, sources, diags), sources, diags);
}

std::optional<ScriptView> ScriptView::loadText(const std::string& path, std::string text,
                                               const frontend::FrontendOptions& options,
                                               SourceManager& sources, DiagnosticEmitter& diags) {
  return fromLowered(frontend::lowerScriptText(path, std::move(text), options, sources, diags),
                     sources, diags);
}

std::optional<ScriptView> ScriptView::fromLowered(std::optional<ir::Module> module,
                                                  SourceManager& sources,
                                                  DiagnosticEmitter& diags) {
  if (!module || diags.hasErrors()) return std::nullopt;
  uint32_t file = module->files().front();
  std::optional<ir::Value> root = frontend::parseYaml(file, sources, diags);
  SMACHAC_CHECK(root.has_value(), "a script that lowered must parse again");
  std::string text(sources.content(file));
  return ScriptView(std::move(*module), file, std::move(text), std::move(*root));
}

ScriptView::ScriptView(ir::Module module, uint32_t file, std::string text, ir::Value root)
    : module_(std::move(module)), file_(file), text_(std::move(text)), root_(std::move(root)) {
  for (const ir::MapEntry& entry : root_.asMap()) {
    if (canonicalKey(entry.key) == "states") states_entry_ = &entry;
  }
  SMACHAC_CHECK(states_entry_ != nullptr, "a lowered script has states");
  collect(states_entry_->value);
  const std::vector<ir::StateId>& children = module_.state(module_.root()).children;
  SMACHAC_CHECK(children.size() == states_.size(), "root states match the module's");
  for (size_t i = 0; i < states_.size(); ++i) states_[i].id = children[i];
}

void ScriptView::collect(const ir::Value& list) {
  for (const ir::Value& item : list.asList()) {
    if (item.isList()) {
      collect(item);
    } else if (item.isMap() && item.asMap().size() == 1) {
      states_.push_back({&item.asMap().front(), &item, &list, {}});
    }
  }
}

std::optional<size_t> ScriptView::find(std::string_view name) const {
  for (size_t i = 0; i < states_.size(); ++i) {
    if (states_[i].name() == name) return i;
  }
  return std::nullopt;
}

std::vector<std::string> ScriptView::names() const {
  std::vector<std::string> names;
  for (const RootState& s : states_) names.push_back(s.name());
  return names;
}

const ir::MapEntry* findKey(const ir::Value& map, std::string_view longhand) {
  std::optional<size_t> index = findKeyIndex(map, longhand);
  return index ? &map.asMap()[*index] : nullptr;
}

std::optional<size_t> findKeyIndex(const ir::Value& map, std::string_view longhand) {
  if (!map.isMap()) return std::nullopt;
  const ir::Map& entries = map.asMap();
  for (size_t i = 0; i < entries.size(); ++i) {
    if (canonicalKey(entries[i].key) == longhand) return i;
  }
  return std::nullopt;
}

bool usesShorthand(const ir::Value& map) {
  if (!map.isMap()) return false;
  for (const ir::MapEntry& entry : map.asMap()) {
    if (frontend::longhandOf(entry.key)) return true;
  }
  return false;
}

std::string keySpelling(std::string_view longhand, bool shorthand) {
  if (shorthand) {
    for (std::string_view s : kWrittenShorthands) {
      if (frontend::longhandOf(s) == longhand) return std::string(s);
    }
  }
  return std::string(longhand);
}

}  // namespace smachac::refactor
