// Small lookups on a container's children that several passes share.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/module.h"

namespace smachac::passes {

/// The name of the `index`-th child of `container`.
inline const std::string& childName(const ir::Module& module, const ir::State& container,
                                    uint32_t index) {
  return module.state(container.children[index]).name.text;
}

/// The names of `container`'s children, in order (candidates for "did you mean").
inline std::vector<std::string> childNames(const ir::Module& module, const ir::State& container) {
  std::vector<std::string> names;
  names.reserve(container.children.size());
  for (ir::StateId child : container.children) names.push_back(module.state(child).name.text);
  return names;
}

}  // namespace smachac::passes
