// contain: inferring the container's userdata interface.
#include "refactor/contain_keys.h"

#include <algorithm>
#include <optional>
#include <set>

#include "passes/analysis/userdata_scope.h"

namespace smachac::refactor {
namespace {

using KeySet = std::set<std::string, std::less<>>;

void addUnique(std::vector<std::string>& list, std::string_view name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.emplace_back(name);
}

class KeyInference {
 public:
  KeyInference(const ContainScope& scope, const UserdataPlan& userdata)
      : scope_(scope),
        userdata_(userdata),
        root_(scope.script.module(), scope.script.module().root()),
        first_(scope.selection.first),
        count_(scope.selection.count) {}

  KeyPlan run() {
    std::vector<KeySet> defined = definedOnEntry();
    for (size_t l = 0; l < count_; ++l) {
      for (const passes::KeyUse& read : root_.reads(static_cast<uint32_t>(first_ + l))) {
        std::string_view key = read.scope_name->text;
        if (!defined[l].contains(key) && providedOutside(rootName(key))) {
          addUnique(plan_.input_keys, key);
        }
      }
    }
    KeySet outer_reads = outerReads();
    for (const std::string& key : innerDefinitions()) {
      if (outer_reads.contains(rootName(key))) addUnique(plan_.output_keys, key);
    }
    for (const std::vector<std::string>* keys : {&plan_.input_keys, &plan_.output_keys}) {
      for (const std::string& key : *keys) {
        std::string root_name(rootName(key));
        auto pair = std::make_pair(key, root_name);
        bool listed = std::find(plan_.remapping.begin(), plan_.remapping.end(), pair) !=
                      plan_.remapping.end();
        if (root_name != key && !listed) plan_.remapping.push_back(pair);
      }
    }
    return std::move(plan_);
  }

 private:
  std::string_view rootName(std::string_view key) const {
    auto it = userdata_.renamed.find(key);
    return it == userdata_.renamed.end() ? key : std::string_view(it->second);
  }

  KeySet writes(size_t l) const {
    KeySet keys;
    for (const passes::KeyUse& w : root_.writes(static_cast<uint32_t>(first_ + l))) {
      keys.insert(w.scope_name->text);
    }
    return keys;
  }

  /// Keys written by the selected states, then set by userdata staying inside.
  std::vector<std::string> innerDefinitions() const {
    std::vector<std::string> keys;
    for (size_t l = 0; l < count_; ++l) {
      for (const passes::KeyUse& w : root_.writes(static_cast<uint32_t>(first_ + l))) {
        addUnique(keys, w.scope_name->text);
      }
    }
    for (const std::string& key : userdata_.inner_literals) addUnique(keys, key);
    return keys;
  }

  bool providedOutside(std::string_view key) const {
    if (std::find(userdata_.added.begin(), userdata_.added.end(), key) != userdata_.added.end()) {
      return true;
    }
    for (const passes::LiteralDef& def : root_.literals()) {
      bool outside =
          def.child == passes::UserdataScope::kContainer || !scope_.selection.contains(def.child);
      if (outside && root_.keyName(def.key) == key) return true;
    }
    for (uint32_t c = 0; c < root_.childCount(); ++c) {
      if (scope_.selection.contains(c)) continue;
      for (const passes::KeyUse& w : root_.writes(c)) {
        if (w.scope_name->text == key) return true;
      }
    }
    return false;
  }

  KeySet outerReads() const {
    KeySet keys;
    for (uint32_t c = 0; c < root_.childCount(); ++c) {
      if (scope_.selection.contains(c)) continue;
      for (const passes::KeyUse& r : root_.reads(c)) keys.insert(r.scope_name->text);
    }
    return keys;
  }

  /// The keys defined inside when each selected state starts.
  std::vector<KeySet> definedOnEntry() const {
    KeySet initial(userdata_.inner_literals.begin(), userdata_.inner_literals.end());
    std::vector<KeySet> in(count_, initial);
    if (scope_.concurrence()) return in;
    std::vector<std::vector<size_t>> preds = predecessors();
    std::vector<bool> reachable = reachableFromFirst();
    std::vector<std::optional<KeySet>> out(count_);
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t l = 0; l < count_; ++l) {
        if (!reachable[l]) continue;
        std::optional<KeySet> entry = l == 0 ? initial : meet(preds[l], out, reachable);
        if (!entry) continue;  // no predecessor known yet: still "everything"
        KeySet exit = *entry;
        for (const std::string& key : writes(l)) exit.insert(key);
        in[l] = std::move(*entry);
        if (out[l] != exit) {
          out[l] = std::move(exit);
          changed = true;
        }
      }
    }
    return in;
  }

  /// The intersection of the predecessors' exits known so far (unknown ones are "every
  /// key", the start of a must-analysis); nullopt when none is known.
  static std::optional<KeySet> meet(const std::vector<size_t>& preds,
                                    const std::vector<std::optional<KeySet>>& out,
                                    const std::vector<bool>& reachable) {
    std::optional<KeySet> result;
    for (size_t p : preds) {
      if (!reachable[p] || !out[p]) continue;
      if (!result) {
        result = *out[p];
        continue;
      }
      KeySet both;
      std::set_intersection(result->begin(), result->end(), out[p]->begin(), out[p]->end(),
                            std::inserter(both, both.end()));
      result = std::move(both);
    }
    return result;
  }

  std::vector<std::vector<size_t>> predecessors() const {
    std::vector<std::vector<size_t>> preds(count_);
    for (size_t l = 0; l < count_; ++l) {
      for (const ir::Transition& t : scope_.state(first_ + l).transitions) {
        std::optional<size_t> target = scope_.selectedIndex(t.target.text);
        if (target) preds[*target - first_].push_back(l);
      }
    }
    return preds;
  }

  std::vector<bool> reachableFromFirst() const {
    std::vector<bool> seen(count_, false);
    std::vector<size_t> work{0};
    seen[0] = true;
    while (!work.empty()) {
      size_t l = work.back();
      work.pop_back();
      for (const ir::Transition& t : scope_.state(first_ + l).transitions) {
        std::optional<size_t> target = scope_.selectedIndex(t.target.text);
        if (target && !seen[*target - first_]) {
          seen[*target - first_] = true;
          work.push_back(*target - first_);
        }
      }
    }
    return seen;
  }

  const ContainScope& scope_;
  const UserdataPlan& userdata_;
  passes::UserdataScope root_;
  size_t first_;
  size_t count_;
  KeyPlan plan_;
};

}  // namespace

KeyPlan inferKeys(const ContainScope& scope, const UserdataPlan& userdata) {
  return KeyInference(scope, userdata).run();
}

}  // namespace smachac::refactor
