// Userdata keys in scope.
#include "lsp/features/completion_userdata.h"

#include <algorithm>
#include <string>

namespace smachac::lsp {
namespace {

class KeyCollector {
 public:
  void add(const std::string& key, const std::string& detail) {
    bool known = std::any_of(candidates_.begin(), candidates_.end(),
                             [&](const Candidate& c) { return c.label == key; });
    if (!known && !key.empty()) candidates_.push_back({key, ItemKind::Variable, detail, ""});
  }

  void addAll(const std::vector<ScopeName>& keys, const std::string& detail) {
    for (const ScopeName& key : keys) add(key.text, detail);
  }

  /// The keys `state` writes, as its container sees them (through its remapping).
  void addOutputs(const ScopeState& state) {
    std::vector<std::pair<std::string, std::string>> remapping = state.mapPairs("remapping");
    for (const ScopeName& key : state.listed("output_keys")) {
      auto remapped = std::find_if(remapping.begin(), remapping.end(),
                                   [&](const auto& pair) { return pair.first == key.text; });
      add(remapped == remapping.end() ? key.text : remapped->second,
          "output key of " + state.name());
    }
  }

  /// What a container holds for its states: its userdata, input and output keys, and what
  /// its states other than `except` set and write.
  void addContainer(const ScopeState& container, const std::string& except) {
    addAll(container.mapKeys("userdata"), "userdata of " + container.name());
    addAll(container.listed("input_keys"), "input key of " + container.name());
    addAll(container.listed("output_keys"), "output key of " + container.name());
    for (const ScopeState& child : container.children()) {
      if (child.name() == except) continue;
      addOutputs(child);
      if (!child.isContainer()) addAll(child.mapKeys("userdata"), "userdata of " + child.name());
    }
  }

  std::vector<Candidate> take() { return std::move(candidates_); }

 private:
  std::vector<Candidate> candidates_;
};

}  // namespace

std::vector<Candidate> userdataCandidates(const std::vector<ScopeState>& chain,
                                          std::string_view list_key) {
  if (chain.empty()) return {};
  const ScopeState& state = chain.back();
  KeyCollector keys;
  keys.addAll(state.mapKeys("userdata"), "userdata of " + state.name());
  if (state.isContainer()) {
    for (const ScopeState& child : state.children()) keys.addOutputs(child);
  }
  for (size_t i = chain.size() - 1; i-- > 0;) {
    keys.addContainer(chain[i], chain[i + 1].name());
  }
  std::vector<Candidate> candidates = keys.take();
  if (!list_key.empty()) {
    std::vector<ScopeName> listed = state.listed(list_key);
    std::erase_if(candidates, [&](const Candidate& c) { return contains(listed, c.label); });
  }
  return candidates;
}

std::vector<Candidate> remapKeyCandidates(const ScopeState& state) {
  std::vector<ScopeName> remapped = state.mapKeys("remapping");
  std::vector<Candidate> candidates;
  for (const char* list : {"input_keys", "output_keys"}) {
    std::string detail = list == std::string_view("input_keys") ? "input key" : "output key";
    for (const ScopeName& key : state.listed(list)) {
      bool offered = std::any_of(candidates.begin(), candidates.end(),
                                 [&](const Candidate& c) { return c.label == key.text; });
      if (!contains(remapped, key.text) && !offered) {
        candidates.push_back({key.text, ItemKind::Variable, detail, ""});
      }
    }
  }
  return candidates;
}

}  // namespace smachac::lsp
