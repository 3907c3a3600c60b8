// Userdata key types per container scope.
#include "passes/analysis/key_types.h"

#include <unordered_set>

#include "passes/analysis/userdata_scope.h"

namespace smachac::passes {

std::optional<ir::Type> KeyTypes::find(ir::StateId container, std::string_view key) {
  const Table& types = table(container);
  auto it = types.find(std::string(key));
  if (it == types.end()) return std::nullopt;
  return it->second;
}

const KeyTypes::Table& KeyTypes::table(ir::StateId container) {
  auto it = tables_.find(container.index);
  if (it != tables_.end()) return it->second;
  Table built = build(container);
  return tables_[container.index] = std::move(built);
}

KeyTypes::Table KeyTypes::build(ir::StateId container) {
  Table types;
  UserdataScope scope(module_, container);
  for (const std::string& name : scope.keyNames()) types.emplace(name, ir::Type::any());
  std::unordered_set<std::string_view> with_literal;
  for (const LiteralDef& def : scope.literals()) {
    std::string_view name = scope.keyName(def.key);
    types.insert_or_assign(std::string(name), ir::Type::ofValue(def.arg->value));
    with_literal.insert(name);
  }
  const ir::State& state = module_.state(container);
  if (!state.parent.valid()) return types;
  for (const ir::Name& key : state.input_keys) {
    if (with_literal.contains(key.text)) continue;
    std::optional<ir::Type> outer = find(state.parent, remappedName(state, key).text);
    types.insert_or_assign(key.text, outer.value_or(ir::Type::any()));
  }
  return types;
}

}  // namespace smachac::passes
