// contain: the container's outcomes, transitions and (Concurrence) outcome_map. Rules:
//   * every distinct target outside the selection of a selected state's transition, in
//     script order, gets a container outcome `<name lower>_outcome_<k>` (k from 1, skipping
//     names already taken) with a transition to that target; the inner transition now ends
//     the container with that outcome
//   * an outcome a selected state declares without a transition ended the script with that
//     outcome; it passes through: the container gets the same outcome, without transition
//   * a container that would get no outcome at all, around a leaf that leaves its outcomes to
//     its template, passes through every outcome of the script (the leaf ended the script
//     with them before)
//   * StateMachine: inner transitions are rewritten, transitions inside the selection kept
//   * Concurrence (as SMACHA): the selected states' transitions are deleted; for each
//     container outcome, each state contributes the first of its outcomes that leads there,
//     directly or by following the selected states' transitions under the same outcome
//     name; `<name lower>_default_outcome` is added last, and its transition goes to
//     --default-target if given, else to the target of the first container outcome (SMACHA
//     made it a self-loop); with no outcome at all, --default-target is required
//   * a non-selected root state's transition to a selected state now goes to the container;
//     to another than the first selected state is contain-entry-changed (the container
//     always starts at its first state)
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "refactor/contain_scope.h"

namespace smachac::refactor {

struct ContainerOutcome {
  std::string name;
  std::optional<std::string> target;  ///< none: ends the script with the same outcome
};

struct OutcomeCondition {
  std::string state;
  std::string outcome;
};

struct OutcomeMapEntry {
  std::string outcome;
  std::vector<OutcomeCondition> conditions;
};

struct OutcomePlan {
  std::vector<ContainerOutcome> outcomes;  ///< the default outcome last
  std::vector<OutcomeMapEntry> outcome_map;
  std::optional<std::string> default_outcome;
};

/// New targets of root states' transitions, applied to the text once per state: an
/// existing entry's value is replaced, a missing one (a transition that came from a
/// sub-script) is added to the state's `transitions`.
class TransitionEdits {
 public:
  void set(size_t root_index, std::string outcome, std::string target);
  void apply(const ContainScope& scope) const;

 private:
  std::map<size_t, std::vector<std::pair<std::string, std::string>>> changes_;
};

/// Plans the outcomes and records the transition edits; nullopt on errors.
std::optional<OutcomePlan> planOutcomes(const ContainScope& scope, TransitionEdits& transitions);

/// Redirects the other root states' transitions into the container.
void redirectIntoContainer(const ContainScope& scope, TransitionEdits& transitions);

}  // namespace smachac::refactor
