// contain: outcomes, transitions and outcome_map of the new container.
#include "refactor/contain_outcomes.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "ir/support/suggest.h"
#include "refactor/flow_text.h"

namespace smachac::refactor {
namespace {

const ir::Transition* findTransition(const ir::State& state, std::string_view outcome) {
  for (const ir::Transition& t : state.transitions) {
    if (t.outcome.text == outcome) return &t;
  }
  return nullptr;
}

/// Declared outcomes without a transition: they end the enclosing container.
std::vector<std::string> passingOutcomes(const ir::State& state) {
  std::vector<std::string> outcomes;
  for (const ir::Name& outcome : state.outcomes) {
    if (!findTransition(state, outcome.text)) outcomes.push_back(outcome.text);
  }
  return outcomes;
}

std::optional<size_t> findExact(const ir::Value& map, std::string_view key) {
  if (!map.isMap()) return std::nullopt;
  for (size_t i = 0; i < map.asMap().size(); ++i) {
    if (map.asMap()[i].key == key) return i;
  }
  return std::nullopt;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

class OutcomePlanner {
 public:
  OutcomePlanner(const ContainScope& scope, TransitionEdits& transitions)
      : scope_(scope), transitions_(transitions), stem_(lowercase(scope.request.name)) {
    for (size_t i = scope.selection.first; i <= scope.selection.last(); ++i) {
      taken_.insert(scope.root(i).name());
    }
  }

  std::optional<OutcomePlan> run() {
    for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) collect(i);
    if (plan_.outcomes.empty() && someOutcomesUnknown()) passScriptOutcomes();
    if (!scope_.concurrence()) return std::move(plan_);
    mapConcurrence();
    if (!addDefault()) return std::nullopt;
    deleteSelectedTransitions();
    return std::move(plan_);
  }

 private:
  void collect(size_t index) {
    const ir::State& state = scope_.state(index);
    for (const ir::Transition& t : state.transitions) {
      if (scope_.selectedIndex(t.target.text)) continue;
      std::string outcome = outcomeFor(t.target.text);
      if (!scope_.concurrence()) transitions_.set(index, t.outcome.text, outcome);
    }
    for (const std::string& outcome : passingOutcomes(state)) passThrough(outcome);
  }

  bool someOutcomesUnknown() const {
    for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) {
      const ir::State& state = scope_.state(i);
      if (!ir::isContainer(state.kind) && state.outcomes.empty()) return true;
    }
    return false;
  }

  void passScriptOutcomes() {
    const ir::Module& module = scope_.script.module();
    for (const ir::Name& o : module.state(module.root()).outcomes) passThrough(o.text);
  }

  std::string fresh(const std::string& wanted) {
    std::string name = wanted;
    if (taken_.contains(name)) {
      for (size_t n = 1; taken_.contains(name); ++n) name = fmt::format("{}_{}", wanted, n);
    }
    taken_.insert(name);
    return name;
  }

  std::string outcomeFor(const std::string& target) {
    auto it = by_target_.find(target);
    if (it != by_target_.end()) return plan_.outcomes[it->second].name;
    std::string name;
    do {
      name = fmt::format("{}_outcome_{}", stem_, next_k_++);
    } while (taken_.contains(name));
    taken_.insert(name);
    by_target_[target] = plan_.outcomes.size();
    plan_.outcomes.push_back({name, target});
    return name;
  }

  void passThrough(const std::string& outcome) {
    for (const ContainerOutcome& existing : plan_.outcomes) {
      if (existing.name == outcome) return;
    }
    taken_.insert(outcome);
    plan_.outcomes.push_back({outcome, std::nullopt});
  }

  /// The container outcome that `outcome` of selected state `index` leads to, following
  /// the selected states' transitions under the same outcome name.
  std::optional<std::string> follow(size_t index, const std::string& outcome) const {
    std::set<size_t> visited;
    while (visited.insert(index).second) {
      const ir::State& state = scope_.state(index);
      const ir::Transition* t = findTransition(state, outcome);
      if (!t) {
        std::vector<std::string> passing = passingOutcomes(state);
        bool passes = std::find(passing.begin(), passing.end(), outcome) != passing.end();
        return passes ? std::optional<std::string>(outcome) : std::nullopt;
      }
      std::optional<size_t> next = scope_.selectedIndex(t->target.text);
      if (!next) return plan_.outcomes[by_target_.at(t->target.text)].name;
      index = *next;
    }
    return std::nullopt;
  }

  std::vector<std::string> candidateOutcomes(size_t index) const {
    std::vector<std::string> outcomes;
    for (const ir::Transition& t : scope_.state(index).transitions)
      outcomes.push_back(t.outcome.text);
    for (const std::string& o : passingOutcomes(scope_.state(index))) outcomes.push_back(o);
    return outcomes;
  }

  void mapConcurrence() {
    for (const ContainerOutcome& outcome : plan_.outcomes) {
      OutcomeMapEntry entry{outcome.name, {}};
      for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) {
        for (const std::string& o : candidateOutcomes(i)) {
          if (follow(i, o) != outcome.name) continue;
          entry.conditions.push_back({scope_.root(i).name(), o});
          break;
        }
      }
      if (!entry.conditions.empty()) plan_.outcome_map.push_back(std::move(entry));
    }
  }

  std::optional<std::string> defaultTarget() const {
    const ContainRequest& request = scope_.request;
    if (!request.default_target) {
      if (plan_.outcomes.empty()) return std::nullopt;
      const ContainerOutcome& first = plan_.outcomes.front();
      return first.target.value_or(first.name);
    }
    const std::string& target = *request.default_target;
    std::vector<std::string> candidates{request.name};
    for (size_t i = 0; i < scope_.script.states().size(); ++i) {
      if (!scope_.selection.contains(i)) candidates.push_back(scope_.root(i).name());
    }
    const ir::Module& module = scope_.script.module();
    for (const ir::Name& o : module.state(module.root()).outcomes) candidates.push_back(o.text);
    if (std::find(candidates.begin(), candidates.end(), target) != candidates.end()) return target;
    scope_.diags.emit<DiagKind::UnknownDefaultTarget>(SourceLoc{}, target,
                                                      didYouMean(target, candidates));
    return std::nullopt;
  }

  bool addDefault() {
    bool has_outcomes = !plan_.outcomes.empty();
    std::optional<std::string> target = defaultTarget();
    std::string name = fresh(stem_ + "_default_outcome");
    if (!target) {
      if (!has_outcomes && !scope_.request.default_target) {
        scope_.diags.emit<DiagKind::NoDefaultTarget>(
            scope_.root(scope_.selection.first).entry->key_loc, name);
      }
      return false;
    }
    plan_.outcomes.push_back({name, *target});
    plan_.default_outcome = name;
    return true;
  }

  void deleteSelectedTransitions() const {
    for (size_t i = scope_.selection.first; i <= scope_.selection.last(); ++i) {
      const ir::Value& body = scope_.root(i).body();
      if (std::optional<size_t> t = findKeyIndex(body, "transitions")) {
        scope_.deletions.add(body, *t);
      }
    }
  }

  const ContainScope& scope_;
  TransitionEdits& transitions_;
  std::string stem_;
  OutcomePlan plan_;
  std::map<std::string, size_t> by_target_;
  std::set<std::string> taken_;
  size_t next_k_ = 1;
};

}  // namespace

void TransitionEdits::set(size_t root_index, std::string outcome, std::string target) {
  changes_[root_index].emplace_back(std::move(outcome), std::move(target));
}

void TransitionEdits::apply(const ContainScope& scope) const {
  MapEditor maps = scope.maps();
  for (const auto& [index, changes] : changes_) {
    const ir::Value& body = scope.root(index).body();
    std::optional<size_t> t = findKeyIndex(body, "transitions");
    const ir::Value* map = t ? &body.asMap()[*t].value : nullptr;
    std::vector<std::pair<std::string, std::string>> added;
    for (const auto& [outcome, target] : changes) {
      std::optional<size_t> entry = map ? findExact(*map, outcome) : std::nullopt;
      if (entry) {
        maps.replaceValue(*map, *entry, flowScalar(target));
      } else {
        added.emplace_back(outcome, flowScalar(target));
      }
    }
    if (added.empty()) continue;
    if (map && map->isMap()) {
      for (const auto& [outcome, target] : added) maps.append(*map, flowScalar(outcome), target);
    } else if (map) {
      maps.replaceValue(body, *t, flowMap(added));
    } else {
      maps.append(body, keySpelling("transitions", usesShorthand(body)), flowMap(added));
    }
  }
}

std::optional<OutcomePlan> planOutcomes(const ContainScope& scope, TransitionEdits& transitions) {
  return OutcomePlanner(scope, transitions).run();
}

void redirectIntoContainer(const ContainScope& scope, TransitionEdits& transitions) {
  const std::string& first = scope.root(scope.selection.first).name();
  for (size_t i = 0; i < scope.script.states().size(); ++i) {
    if (scope.selection.contains(i)) continue;
    for (const ir::Transition& t : scope.state(i).transitions) {
      if (!scope.selectedIndex(t.target.text)) continue;
      transitions.set(i, t.outcome.text, scope.request.name);
      if (t.target.text != first) {
        scope.diags.emit<DiagKind::ContainEntryChanged>(t.target.loc, scope.root(i).name(),
                                                        t.target.text, scope.request.name, first);
      }
    }
  }
}

}  // namespace smachac::refactor
