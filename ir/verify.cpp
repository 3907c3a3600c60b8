// Structural IR verification.
#include "ir/verify.h"

#include <fmt/core.h>

#include <vector>

namespace smachac::ir {
namespace {

std::optional<std::string> verifyState(const Module& m, StateId id, std::vector<bool>& seen) {
  if (seen[id.index]) return fmt::format("state `{}` is reached twice", m.path(id));
  seen[id.index] = true;
  const State& s = m.state(id);
  if (!isContainer(s.kind) && !s.children.empty()) {
    return fmt::format("leaf `{}` has children", m.path(id));
  }
  if (s.kind == StateKind::Base && id != m.root()) {
    return fmt::format("`{}` is a base state below the root", m.path(id));
  }
  for (StateId child : s.children) {
    if (!child.valid() || child.index >= m.stateCount()) return "dangling child id";
    if (m.state(child).parent != id) {
      return fmt::format("`{}` does not point back to its parent", m.path(child));
    }
    if (auto error = verifyState(m, child, seen)) return error;
  }
  for (const Transition& t : s.transitions) {
    if (t.target_kind != TargetKind::Sibling) continue;
    if (!t.target_state.valid() || m.state(t.target_state).parent != s.parent) {
      return fmt::format("transition `{}` of `{}` resolves to a non-sibling", t.outcome.text,
                         m.path(id));
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> verify(const Module& module) {
  if (!module.root().valid()) return "the module has no root";
  const State& root = module.state(module.root());
  if (root.kind != StateKind::Base) return "the root is not a base state";
  if (root.parent.valid()) return "the root has a parent";
  std::vector<bool> seen(module.stateCount(), false);
  return verifyState(module, module.root(), seen);
}

}  // namespace smachac::ir
