// check-transitions: the transitions of the children of every StateMachine and of the root,
// with SMACH's rules (state_machine.py: check_state_spec when a state is added,
// check_consistency before it runs).
//   * unknown-transition-target  a target that is neither a sibling state nor an outcome of
//                                the container (did you mean: siblings and outcomes; without
//                                a close one, the container's outcomes are listed)
//   * undeclared-outcome         a transition on an outcome the state does not declare; only
//                                for states whose outcomes are known (outcomes.h)
//   * unmapped-outcome           a declared outcome with no transition that is not an outcome
//                                of the container either (SMACH ends the container with it)
//   * unused-container-outcome   an outcome of the container that no child can end it with
//                                (not checked when a child's outcomes are unknown or one of
//                                its transitions is unresolved)
//   * ignored-transitions        a child of a Concurrence with transitions: SMACH ignores them
#include <string>
#include <vector>

#include "ir/support/suggest.h"
#include "passes/analysis/children.h"
#include "passes/analysis/outcomes.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

class TransitionChecker {
 public:
  TransitionChecker(const ir::Module& module, const ir::State& container, DiagnosticEmitter& d)
      : module_(module), container_(container), diags_(d), outcomes_(nameSet(container.outcomes)) {}

  void run() {
    bool outcomes_known = !container_.children.empty();  // empty: an error of its own
    for (ir::StateId id : container_.children) {
      const ir::State& child = module_.state(id);
      for (const ir::Transition& t : child.transitions) {
        checkTransition(child, t);
        outcomes_known = outcomes_known && t.target_kind != ir::TargetKind::Unresolved;
      }
      for (const ir::Name* outcome : unmappedOutcomes(child)) checkUnmapped(child, *outcome);
      outcomes_known = outcomes_known && declaresOutcomes(child);
    }
    if (outcomes_known) reportUnusedOutcomes();
  }

 private:
  void checkTransition(const ir::State& child, const ir::Transition& t) {
    if (t.target_kind == ir::TargetKind::Unresolved) {
      std::optional<std::string> match = closestMatch(t.target.text, targets());
      diags_.emit<DiagKind::UnknownTransitionTarget>(t.target.loc, t.target.text,
                                                     container_.name.text, suggestion(match));
      diags_.fixIt(match);
    } else if (t.target_kind == ir::TargetKind::ContainerOutcome) {
      used_.insert(t.target.text);
    }
    if (declaresOutcomes(child) && !contains(child.outcomes, t.outcome.text)) {
      std::optional<std::string> match = closestMatch(t.outcome.text, nameTexts(child.outcomes));
      diags_.emit<DiagKind::UndeclaredOutcome>(t.outcome.loc, child.name.text, t.outcome.text,
                                               didYouMean(match));
      diags_.fixIt(match);
    }
  }

  void checkUnmapped(const ir::State& child, const ir::Name& outcome) {
    if (outcomes_.contains(outcome.text)) {
      used_.insert(outcome.text);
      return;
    }
    diags_.emit<DiagKind::UnmappedOutcome>(outcome.loc, outcome.text, child.name.text,
                                           container_.name.text);
  }

  void reportUnusedOutcomes() {
    NameSet reported;
    for (const ir::Name& outcome : container_.outcomes) {
      if (used_.contains(outcome.text) || !reported.insert(outcome.text).second) continue;
      diags_.emit<DiagKind::UnusedContainerOutcome>(
          outcome.loc, container_.name.text, outcome.text,
          "no transition or outcome of its states leads to it");
    }
  }

  /// "did you mean" a close sibling or outcome; without one, the container's outcomes.
  std::string suggestion(const std::optional<std::string>& match) {
    std::string close = didYouMean(match);
    if (!close.empty() || container_.outcomes.empty()) return close;
    return "; the outcomes of `" + container_.name.text + "` are " +
           quotedList(nameTexts(container_.outcomes));
  }

  /// Sibling names then container outcomes, for suggestions (built on first use).
  const std::vector<std::string>& targets() {
    if (targets_.empty()) {
      targets_ = childNames(module_, container_);
      for (const ir::Name& outcome : container_.outcomes) targets_.push_back(outcome.text);
    }
    return targets_;
  }

  const ir::Module& module_;
  const ir::State& container_;
  DiagnosticEmitter& diags_;
  NameSet outcomes_;
  NameSet used_;
  std::vector<std::string> targets_;
};

void checkConcurrenceChildren(const ir::Module& module, const ir::State& container,
                              DiagnosticEmitter& diags) {
  for (ir::StateId id : container.children) {
    const ir::State& child = module.state(id);
    if (child.transitions.empty()) continue;
    diags.emit<DiagKind::IgnoredTransitions>(child.transitions.front().outcome.loc, child.name.text,
                                             container.name.text);
  }
}

}  // namespace

void checkTransitions(const ir::Module& module, PassContext& context) {
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    if (isSequential(state.kind)) {
      TransitionChecker(module, state, context.diags).run();
    } else if (state.kind == ir::StateKind::Concurrence) {
      checkConcurrenceChildren(module, state, context.diags);
    }
  }
}

}  // namespace smachac::passes
