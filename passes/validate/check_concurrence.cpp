// check-concurrence: Concurrence containers, with SMACH's semantics (concurrence.py): every
// child runs; when all have finished, the satisfied `outcome_map` entry with the most
// conditions gives the outcome, the first in map order (sorted by outcome) among equals; an
// entry without conditions is never chosen; if none is chosen, the default_outcome is. That is
// SMACH 2.5's rule, stated in stdlib/runtime/README.md ("Choosing among outcome_map
// entries"); older SMACH takes the last satisfied entry instead, so where the two differ this
// check says so rather than claim one behaviour.
//   * missing-key                    no `default_outcome` (SMACH requires one)
//   * unknown-default-outcome        `default_outcome` is not an outcome of the concurrence
//   * unknown-outcome-map-outcome    an `outcome_map` key is not an outcome of the concurrence
//   * unknown-outcome-map-child      a condition names a state that is not a child
//   * undeclared-outcome             a condition names an outcome its child does not declare
//   * shadowed-outcome-map-entry     an entry SMACH 2.5 never chooses: it has no conditions,
//                                    or an earlier entry has exactly the same ones
//   * version-dependent-outcome-map  two entries that can hold together (no child needs two
//                                    outcomes) of which SMACH 2.5 chooses the earlier (more
//                                    conditions, or as many) and older SMACH the later
//   * unused-container-outcome       an outcome neither in `outcome_map` nor the default
//   * concurrent-write               two children write the same userdata key (after remapping)
//   * ignored-concurrence-key        `outcome_map` or `default_outcome` on another kind of state
#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ir/support/suggest.h"
#include "passes/analysis/children.h"
#include "passes/analysis/outcomes.h"
#include "passes/analysis/userdata_scope.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

/// An entry's conditions as (child, child outcome), sorted.
using Conditions = std::vector<std::pair<std::string_view, std::string_view>>;

/// An outcome_map entry whose conditions all name real children and outcomes.
struct ValidEntry {
  const ir::OutcomeMapEntry* entry;
  Conditions conditions;
};

class ConcurrenceChecker {
 public:
  ConcurrenceChecker(const ir::Module& module, ir::StateId id, DiagnosticEmitter& diags)
      : module_(module),
        id_(id),
        c_(module.state(id)),
        diags_(diags),
        outcomes_(nameSet(c_.outcomes)) {
    for (ir::StateId child : c_.children) children_.emplace(module.state(child).name.text, child);
  }

  void run() {
    checkDefaultOutcome();
    std::vector<ValidEntry> valid;
    for (const ir::OutcomeMapEntry& entry : c_.outcome_map) {
      if (checkEntry(entry)) valid.push_back(validEntry(entry));
    }
    reportOrderRules(valid);
    reportUnusedOutcomes();
    reportConcurrentWrites();
  }

 private:
  void checkDefaultOutcome() {
    if (!c_.default_outcome) {
      diags_.emit<DiagKind::MissingKey>(c_.name.loc, "concurrence `" + c_.name.text + "`",
                                        "default_outcome");
      return;
    }
    const ir::Name& outcome = *c_.default_outcome;
    if (outcomes_.contains(outcome.text)) return;
    std::optional<std::string> match = closestMatch(outcome.text, nameTexts(c_.outcomes));
    diags_.emit<DiagKind::UnknownDefaultOutcome>(outcome.loc, outcome.text, c_.name.text,
                                                 didYouMean(match));
    diags_.fixIt(match);
  }

  /// Reports the entry's problems; returns whether it has none.
  bool checkEntry(const ir::OutcomeMapEntry& entry) {
    bool ok = true;
    if (!outcomes_.contains(entry.outcome.text)) {
      std::optional<std::string> match = closestMatch(entry.outcome.text, nameTexts(c_.outcomes));
      diags_.emit<DiagKind::UnknownOutcomeMapOutcome>(entry.outcome.loc, entry.outcome.text,
                                                      c_.name.text, didYouMean(match));
      diags_.fixIt(match);
      ok = false;
    }
    for (const ir::OutcomeCondition& condition : entry.conditions) {
      ok = checkCondition(condition) && ok;
    }
    return ok;
  }

  bool checkCondition(const ir::OutcomeCondition& condition) {
    auto it = children_.find(condition.child.text);
    if (it == children_.end()) {
      std::optional<std::string> match =
          closestMatch(condition.child.text, childNames(module_, c_));
      diags_.emit<DiagKind::UnknownOutcomeMapChild>(condition.child.loc, condition.child.text,
                                                    c_.name.text, didYouMean(match));
      diags_.fixIt(match);
      return false;
    }
    const ir::State& child = module_.state(it->second);
    if (!declaresOutcomes(child) || contains(child.outcomes, condition.child_outcome.text)) {
      return true;
    }
    std::optional<std::string> match =
        closestMatch(condition.child_outcome.text, nameTexts(child.outcomes));
    diags_.emit<DiagKind::UndeclaredOutcome>(condition.child_outcome.loc, child.name.text,
                                             condition.child_outcome.text, didYouMean(match));
    diags_.fixIt(match);
    return false;
  }

  static ValidEntry validEntry(const ir::OutcomeMapEntry& entry) {
    ValidEntry valid{&entry, {}};
    for (const ir::OutcomeCondition& condition : entry.conditions) {
      valid.conditions.emplace_back(condition.child.text, condition.child_outcome.text);
    }
    std::sort(valid.conditions.begin(), valid.conditions.end());
    return valid;
  }

  /// Reports what SMACH 2.5 and older SMACH decide differently, in map order.
  void reportOrderRules(std::vector<ValidEntry>& entries) {
    std::sort(entries.begin(), entries.end(), [](const ValidEntry& a, const ValidEntry& b) {
      return a.entry->outcome.text < b.entry->outcome.text;
    });
    for (size_t i = 0; i < entries.size(); ++i) {
      reportNeverChosen(entries, i);
      for (size_t j = i + 1; j < entries.size(); ++j) {
        reportVersionDependent(entries[i], entries[j]);
      }
    }
  }

  /// SMACH 2.5 never chooses an entry without conditions, nor one after an entry with exactly
  /// the same conditions (the first wins ties); older SMACH may choose either.
  void reportNeverChosen(const std::vector<ValidEntry>& entries, size_t j) {
    const ir::Name& outcome = entries[j].entry->outcome;
    if (entries[j].conditions.empty()) {
      diags_.emit<DiagKind::ShadowedOutcomeMapEntry>(
          outcome.loc, outcome.text,
          "it has no conditions; older SMACH and the ROS 2 branch choose it when no "
          "entry after it holds");
      return;
    }
    for (size_t i = 0; i < j; ++i) {
      if (entries[i].conditions != entries[j].conditions) continue;
      diags_.emit<DiagKind::ShadowedOutcomeMapEntry>(
          outcome.loc, outcome.text,
          "`" + entries[i].entry->outcome.text +
              "` has the same conditions and comes first; older SMACH and the ROS 2 "
              "branch choose `" +
              outcome.text + "` instead (last in order)");
      return;
    }
  }

  /// `earlier` and `later` in map order, both with conditions and not the same ones.
  void reportVersionDependent(const ValidEntry& earlier, const ValidEntry& later) {
    size_t earlier_size = earlier.conditions.size();
    size_t later_size = later.conditions.size();
    if (later_size == 0 || earlier_size < later_size || earlier.conditions == later.conditions ||
        !canHoldTogether(earlier.conditions, later.conditions)) {
      return;
    }
    const ir::Name& chosen = earlier.entry->outcome;
    const ir::Name& last = later.entry->outcome;
    diags_.emit<DiagKind::VersionDependentOutcomeMap>(
        chosen.loc, chosen.text, last.text, chosen.text,
        earlier_size > later_size ? "more conditions" : "as many conditions and first in order",
        last.text);
  }

  /// Whether no child needs two different outcomes; both lists sorted by child.
  static bool canHoldTogether(const Conditions& a, const Conditions& b) {
    auto x = a.begin();
    auto y = b.begin();
    while (x != a.end() && y != b.end()) {
      if (x->first < y->first) {
        ++x;
      } else if (y->first < x->first) {
        ++y;
      } else if (x++->second != y++->second) {
        return false;
      }
    }
    return true;
  }

  void reportUnusedOutcomes() {
    if (!c_.default_outcome) return;  // already an error
    NameSet used;
    for (const ir::OutcomeMapEntry& entry : c_.outcome_map) used.insert(entry.outcome.text);
    if (c_.default_outcome) used.insert(c_.default_outcome->text);
    used.insert("preempted");  // when it was preempted and every child serviced the request
    for (const ir::Name& outcome : c_.outcomes) {
      if (!used.insert(outcome.text).second) continue;
      diags_.emit<DiagKind::UnusedContainerOutcome>(
          outcome.loc, c_.name.text, outcome.text,
          "it is neither an `outcome_map` key nor the `default_outcome`");
    }
  }

  void reportConcurrentWrites() {
    UserdataScope scope(module_, id_);
    std::unordered_map<uint32_t, std::pair<uint32_t, const KeyUse*>> first;
    for (uint32_t child = 0; child < scope.childCount(); ++child) {
      for (const KeyUse& write : scope.writes(child)) {
        auto [it, inserted] = first.emplace(write.key, std::make_pair(child, &write));
        if (inserted || it->second.first == child) continue;
        diags_.emit<DiagKind::ConcurrentWrite>(write.scope_name->loc, childName(module_, c_, child),
                                               childName(module_, c_, it->second.first),
                                               scope.keyName(write.key), c_.name.text);
        diags_.note<DiagNoteKind::StateWritesKeyHere>(it->second.second->scope_name->loc,
                                                      childName(module_, c_, it->second.first));
      }
    }
  }

  const ir::Module& module_;
  ir::StateId id_;
  const ir::State& c_;
  DiagnosticEmitter& diags_;
  NameSet outcomes_;
  std::unordered_map<std::string_view, ir::StateId> children_;
};

void checkIgnoredKeys(const ir::State& state, DiagnosticEmitter& diags) {
  if (!state.outcome_map.empty()) {
    diags.emit<DiagKind::IgnoredConcurrenceKey>(state.outcome_map.front().outcome.loc,
                                                "outcome_map", state.name.text);
  }
  if (state.default_outcome) {
    diags.emit<DiagKind::IgnoredConcurrenceKey>(state.default_outcome->loc, "default_outcome",
                                                state.name.text);
  }
}

}  // namespace

void checkConcurrence(const ir::Module& module, PassContext& context) {
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    if (state.kind == ir::StateKind::Concurrence) {
      ConcurrenceChecker(module, id, context.diags).run();
    } else {
      checkIgnoredKeys(state, context.diags);
    }
  }
}

}  // namespace smachac::passes
