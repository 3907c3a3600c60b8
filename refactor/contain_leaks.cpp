// contain: keeping the params that leaked from a contained sub-script include.
#include "refactor/contain_leaks.h"

#include "refactor/flow_text.h"
#include "refactor/lookup_rewrite.h"

namespace smachac::refactor {
namespace {

bool includesSubScript(const ir::Value& body) {
  return findKey(body, "script") && !findKey(body, "states");
}

/// The last root state before `index` that includes a sub-script.
std::optional<size_t> lastInclude(const ContainScope& scope, size_t index) {
  for (size_t j = index; j-- > 0;) {
    if (includesSubScript(scope.root(j).body())) return j;
  }
  return std::nullopt;
}

/// Params `state` inherited from the leak: its params that its script text does not set.
std::vector<std::string> leakedKeys(const ir::State& state, const ir::Value& body) {
  std::vector<std::string> keys;
  if (!state.params || !state.params->isMap()) return keys;
  const ir::MapEntry* own = findKey(body, "params");
  for (const ir::MapEntry& e : state.params->asMap()) {
    if (!own || !own->value.find(e.key)) keys.push_back(e.key);
  }
  return keys;
}

void keepFor(const ContainScope& scope, size_t index) {
  const ir::State& state = scope.state(index);
  const ir::Value& body = scope.root(index).body();
  std::vector<std::string> used = usedParams(body, leakedKeys(state, body));
  if (used.empty()) return;
  std::vector<std::pair<std::string, std::string>> entries;
  for (const std::string& key : used) {
    entries.emplace_back(key, flowValue(*state.params->find(key)));
  }
  MapEditor maps = scope.maps();
  const ir::MapEntry* own = findKey(body, "params");
  if (own && own->value.isMap()) {
    for (const auto& [key, value] : entries) maps.append(own->value, flowScalar(key), value);
  } else {
    maps.append(body, keySpelling("params", usesShorthand(body)), flowMap(entries));
  }
}

}  // namespace

void keepLeakedParams(const ContainScope& scope) {
  for (size_t i = scope.selection.last() + 1; i < scope.script.states().size(); ++i) {
    std::optional<size_t> include = lastInclude(scope, i);
    if (include && scope.selection.contains(*include)) keepFor(scope, i);
  }
}

}  // namespace smachac::refactor
