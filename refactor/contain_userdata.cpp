// contain: lifting the selected leaves' userdata to the root.
#include "refactor/contain_userdata.h"

#include <fmt/core.h>

#include <algorithm>
#include <set>

#include "passes/analysis/userdata_scope.h"
#include "refactor/flow_text.h"

namespace smachac::refactor {
namespace {

struct Candidate {
  const ir::MapEntry* entry = nullptr;  ///< the last selected leaf's entry for the key
  size_t state = 0;
  Span span;
};

const ir::Argument* findArgument(const std::vector<ir::Argument>& args, std::string_view key) {
  for (const ir::Argument& a : args) {
    if (a.key.text == key) return &a;
  }
  return nullptr;
}

class UserdataLifter {
 public:
  explicit UserdataLifter(const ContainScope& scope) : scope_(scope) {}

  UserdataPlan run() {
    for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) {
      if (scope_.state(i).kind == ir::StateKind::Leaf) liftFrom(i);
    }
    for (const std::string& key : order_) place(key, candidates_.at(key));
    writeRoot();
    return std::move(plan_);
  }

 private:
  void liftFrom(size_t index) {
    const ir::State& state = scope_.state(index);
    const ir::Value& body = scope_.root(index).body();
    std::optional<size_t> at = findKeyIndex(body, "userdata");
    std::set<std::string> moved;
    if (at) {
      const ir::Value& own = body.asMap()[*at].value;
      std::vector<size_t> lifted;
      for (size_t j = 0; j < own.asMap().size(); ++j) {
        const ir::MapEntry& e = own.asMap()[j];
        const ir::Argument* arg = findArgument(state.userdata, e.key);
        if (!arg || !ir::sameValue(arg->value, e.value)) continue;  // a lookup
        if (!candidates_.contains(e.key)) order_.push_back(e.key);
        candidates_[e.key] = {&e, index, entryValueSpan(scope_.text(), own, e)};
        lifted.push_back(j);
        moved.insert(e.key);
      }
      if (lifted.size() == own.asMap().size()) {
        scope_.deletions.add(body, *at);
      } else {
        scope_.deletions.add(own, lifted);
      }
    }
    for (const ir::Argument& arg : state.userdata) {
      if (!moved.contains(arg.key.text)) addUnique(plan_.inner_literals, arg.key.text);
    }
  }

  static void addUnique(std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }

  /// The values the root scope keeps for `key`: the root's userdata, other root leaves'.
  std::vector<const ir::Value*> rootValues(std::string_view key) const {
    const ir::Module& module = scope_.script.module();
    std::vector<const ir::Value*> values;
    if (const ir::Argument* a = findArgument(module.state(module.root()).userdata, key)) {
      values.push_back(&a->value);
    }
    for (size_t i = 0; i < scope_.script.states().size(); ++i) {
      const ir::State& state = scope_.state(i);
      if (scope_.selection.contains(i) || state.kind != ir::StateKind::Leaf) continue;
      if (const ir::Argument* a = findArgument(state.userdata, key)) values.push_back(&a->value);
    }
    return values;
  }

  void place(const std::string& key, const Candidate& c) {
    std::vector<const ir::Value*> existing = rootValues(key);
    auto same = [&](const ir::Value* v) { return ir::sameValue(*v, c.entry->value); };
    if (std::any_of(existing.begin(), existing.end(), same)) return;
    std::string root_key = key;
    if (!existing.empty()) {
      root_key = freshKey(key);
      plan_.renamed.emplace(key, root_key);
      scope_.diags.emit<DiagKind::LiftedUserdataRenamed>(
          c.entry->key_loc, key, scope_.root(c.state).name(), root_key, key);
    }
    plan_.added.push_back(root_key);
    additions_.emplace_back(root_key,
                            inlineText(scope_.text(), scope_.edits, c.entry->value, c.span));
  }

  std::string freshKey(const std::string& key) const {
    const ir::Module& module = scope_.script.module();
    passes::UserdataScope root(module, module.root());
    for (size_t n = 1;; ++n) {
      std::string candidate = fmt::format("{}_{}", key, n);
      bool added =
          std::find(plan_.added.begin(), plan_.added.end(), candidate) != plan_.added.end();
      if (!root.find(candidate) && !added && !candidates_.contains(candidate)) return candidate;
    }
  }

  void writeRoot() const {
    if (additions_.empty()) return;
    const ir::Value& root = scope_.script.root();
    MapEditor maps = scope_.maps();
    if (const ir::MapEntry* existing = findKey(root, "userdata")) {
      for (const auto& [key, value] : additions_)
        maps.append(existing->value, flowScalar(key), value);
      return;
    }
    std::string key = keySpelling("userdata", usesShorthand(root));
    if (std::optional<size_t> outcomes = findKeyIndex(root, "outcomes")) {
      maps.insertAfter(root, *outcomes, key, flowMap(additions_));
    } else {
      maps.insertBefore(root, *findKeyIndex(root, "states"), key, flowMap(additions_));
    }
  }

  const ContainScope& scope_;
  UserdataPlan plan_;
  std::vector<std::string> order_;
  std::map<std::string, Candidate> candidates_;
  std::vector<std::pair<std::string, std::string>> additions_;
};

}  // namespace

UserdataPlan liftUserdata(const ContainScope& scope) { return UserdataLifter(scope).run(); }

}  // namespace smachac::refactor
