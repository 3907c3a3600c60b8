// fold-trivial-containers: replaces a StateMachine that holds a single state and only passes
// that state's outcomes on with the state itself.
//
//   before                                         after
//   base SEQ  outcomes: [done]                     base SEQ  outcomes: [done]
//     state_machine WRAP  outcomes: [ok]             leaf WRAP  outcomes: [succeeded]
//       {ok -> done (outcome)}                         {succeeded -> done (outcome)}
//       leaf STEP  outcomes: [succeeded]
//         {succeeded -> ok (outcome)}
//
// The state takes the container's name; each of its outcomes gets the container's
// transition for the container outcome it led to (or passes that outcome on); remappings
// compose. Only folded when nothing else can change:
//   * the container is a StateMachine with the template `StateMachine`, inside a
//     StateMachine or the root, with one child and no `userdata`, template arguments,
//     callbacks, `outcome_map` or `default_outcome`; a leaf child has no `userdata` either
//     (it would move from the container's scope to the parent's);
//   * the child declares its outcomes, transitions only on them, and each of them ends the
//     container; an outcome the container passes on under another name must be an outcome
//     of the parent;
//   * the child's input keys come from the container's input keys, its output keys go to
//     the container's output keys, and each output key of the container is written by the
//     child or is an input key.
// Containers are visited innermost first, so nested trivial containers fold into one state.
#include <algorithm>
#include <optional>
#include <vector>

#include "passes/analysis/outcomes.h"
#include "passes/analysis/userdata_scope.h"
#include "passes/optimize/transforms.h"

namespace smachac::passes {
namespace {

bool isBareContainer(const ir::State& c) {
  return c.kind == ir::StateKind::StateMachine && c.template_name &&
         c.template_name->text == "StateMachine" && c.children.size() == 1 && c.userdata.empty() &&
         c.args.empty() && c.callbacks.empty() && c.outcome_map.empty() && !c.default_outcome;
}

/// The container outcome `outcome` of `child` ends `container` with, if it does.
std::optional<ir::Name> endingOutcome(const ir::State& child, const ir::Name& outcome,
                                      const ir::State& container) {
  if (const ir::Transition* t = findTransition(child, outcome.text)) {
    if (t->target_kind != ir::TargetKind::ContainerOutcome) return std::nullopt;
    return t->target;
  }
  if (!contains(container.outcomes, outcome.text)) return std::nullopt;
  return outcome;
}

/// The child's transitions once it replaces `container`, or nullopt if it cannot.
std::optional<std::vector<ir::Transition>> foldedTransitions(const ir::State& child,
                                                             const ir::State& container,
                                                             const ir::State& parent) {
  std::vector<ir::Transition> folded;
  NameSet seen;
  for (const ir::Name& outcome : child.outcomes) {
    if (!seen.insert(outcome.text).second) continue;
    std::optional<ir::Name> ends = endingOutcome(child, outcome, container);
    if (!ends) return std::nullopt;
    if (const ir::Transition* next = findTransition(container, ends->text)) {
      folded.push_back(*next);
      folded.back().outcome = outcome;
    } else if (outcome.text != ends->text) {
      if (!contains(parent.outcomes, ends->text)) return std::nullopt;
      folded.push_back({outcome, *ends, ir::TargetKind::ContainerOutcome, ir::StateId()});
    }
  }
  return folded;
}

/// Whether the child's keys pass through the container's interface unchanged.
bool keysPassThrough(const ir::State& child, const ir::State& container) {
  NameSet written;
  for (const ir::Name& key : child.input_keys) {
    if (!contains(container.input_keys, remappedName(child, key).text)) return false;
  }
  for (const ir::Name& key : child.output_keys) {
    written.insert(remappedName(child, key).text);
    if (!contains(container.output_keys, remappedName(child, key).text)) return false;
  }
  return std::all_of(
      container.output_keys.begin(), container.output_keys.end(), [&](const ir::Name& key) {
        return written.contains(key.text) || contains(container.input_keys, key.text);
      });
}

/// The child's remapping straight into the parent: key -> container key -> parent key.
std::vector<ir::Remap> composedRemapping(const ir::State& child, const ir::State& container) {
  std::vector<ir::Remap> composed;
  NameSet seen;
  auto add = [&](const ir::Name& key) {
    if (!seen.insert(key.text).second) return;
    const ir::Name& parent_key = remappedName(container, remappedName(child, key));
    if (parent_key.text != key.text) composed.push_back({key, parent_key});
  };
  for (const ir::Name& key : child.input_keys) add(key);
  for (const ir::Name& key : child.output_keys) add(key);
  return composed;
}

class Folder {
 public:
  explicit Folder(ir::Module& module) : module_(module) {}

  /// Folds `id` into its only child if it qualifies; returns whether it did.
  bool tryFold(ir::StateId id) {
    const ir::State& container = module_.state(id);
    if (!isBareContainer(container) || !container.parent.valid()) return false;
    const ir::State& parent = module_.state(container.parent);
    ir::StateId child_id = container.children.front();
    const ir::State& child = module_.state(child_id);
    bool child_userdata_in_scope = !ir::isContainer(child.kind) && !child.userdata.empty();
    if (!isSequential(parent.kind) || child_userdata_in_scope || !declaresOutcomes(child)) {
      return false;
    }
    for (const ir::Transition& t : child.transitions) {
      if (!contains(child.outcomes, t.outcome.text)) return false;
    }
    std::optional<std::vector<ir::Transition>> transitions =
        foldedTransitions(child, container, parent);
    if (!transitions || !keysPassThrough(child, container)) return false;
    replace(id, child_id, std::move(*transitions));
    return true;
  }

 private:
  void replace(ir::StateId id, ir::StateId child_id, std::vector<ir::Transition> transitions) {
    ir::State& container = module_.state(id);
    ir::State& child = module_.state(child_id);
    child.remapping = composedRemapping(child, container);
    child.transitions = std::move(transitions);
    child.name = container.name;
    child.parent = container.parent;
    ir::State& parent = module_.state(container.parent);
    std::replace(parent.children.begin(), parent.children.end(), id, child_id);
    container.children.clear();
    container.parent = ir::StateId();
    for (ir::StateId sibling : parent.children) {
      for (ir::Transition& t : module_.state(sibling).transitions) {
        if (t.target_kind == ir::TargetKind::Sibling && t.target_state == id) {
          t.target_state = child_id;
        }
      }
    }
  }

  ir::Module& module_;
};

}  // namespace

bool foldTrivialContainers(ir::Module& module, PassContext&) {
  std::vector<ir::StateId> order = module.preorder();
  Folder folder(module);
  bool changed = false;
  for (auto it = order.rbegin(); it != order.rend(); ++it) changed = folder.tryFold(*it) || changed;
  return changed;
}

}  // namespace smachac::passes
