// Structural invariants of an ir::Module. A violation is a bug in smachac (the frontend or a
// pass built a broken graph), never a user error: verify() returns the first violation found.
// Checked after lowering and after every pass in test builds.
//   * the root exists, is the only Base state, and has no parent
//   * parent and children links agree; only containers have children; no state is reached twice
//   * a transition resolved to a sibling names a child of the same container
#pragma once

#include <optional>
#include <string>

#include "ir/module.h"

namespace smachac::ir {

std::optional<std::string> verify(const Module& module);

}  // namespace smachac::ir
