// contain: the selected states' own `params` move to the container (SMACHA's params lift).
// Rules, per selected state in order and per param in order:
//   * a key the container does not have yet moves as it is
//   * the same key with the same value is shared
//   * the same key with another value moves as `<key>_<n>` (lowest free n >= 1, free in
//     the container and in the state's params), and the state's lookups of it (and those of
//     the states it contains that inherit it) are rewritten
//   * unless the renamed param would reach a sub-script, whose lookups are in another file:
//     then it stays on the state (param-not-lifted), where it wins over the container's
//   * the state's `params` key goes when all its params moved
// Params are inherited by every state of the container, so lookups keep resolving.
#pragma once

#include <string>
#include <vector>

#include "refactor/contain_scope.h"

namespace smachac::refactor {

struct ContainerParam {
  std::string key;
  const ir::Value* value = nullptr;
  Span span;  ///< the value's text in the script (rendered with the edits applied)
};

/// Moves the params (recording the edits); returns the container's params in order.
std::vector<ContainerParam> liftParams(const ContainScope& scope);

}  // namespace smachac::refactor
