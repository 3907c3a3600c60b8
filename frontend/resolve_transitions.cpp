// Transition target resolution.
#include "frontend/resolve_transitions.h"

#include <string_view>
#include <unordered_map>

namespace smachac::frontend {
namespace {

void resolveChildren(ir::Module& module, ir::StateId container) {
  std::unordered_map<std::string_view, ir::StateId> siblings;
  siblings.reserve(module.state(container).children.size());
  for (ir::StateId child : module.state(container).children) {
    siblings.emplace(module.state(child).name.text, child);
  }
  const std::vector<ir::Name>& outcomes = module.state(container).outcomes;
  for (ir::StateId child : module.state(container).children) {
    for (ir::Transition& t : module.state(child).transitions) {
      if (auto it = siblings.find(t.target.text); it != siblings.end()) {
        t.target_kind = ir::TargetKind::Sibling;
        t.target_state = it->second;
        continue;
      }
      t.target_kind = ir::TargetKind::Unresolved;
      for (const ir::Name& outcome : outcomes) {
        if (outcome.text == t.target.text) t.target_kind = ir::TargetKind::ContainerOutcome;
      }
    }
  }
}

}  // namespace

void resolveTransitions(ir::Module& module) {
  for (ir::StateId id : module.preorder()) {
    if (ir::isContainer(module.state(id).kind)) resolveChildren(module, id);
  }
}

}  // namespace smachac::frontend
