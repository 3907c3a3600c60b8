// contain: the container's `input_keys`, `output_keys` and `remapping`, inferred from what
// the selected states read and write (their `input_keys`/`output_keys` through their
// remapping, as check-userdata-flow sees them: passes/analysis/userdata_scope.h). Rules:
//   * defined inside: keys set by userdata that stays in the container (entries with
//     lookups) and, in a StateMachine, keys written on every path from the first selected
//     state to the reader (a forward must-defined dataflow over the selected states'
//     transitions; in a Concurrence the children run in parallel, so writes never count)
//   * input key: a key a selected state reads that is not defined inside at that read and
//     that the root provides: the root's userdata (lifted entries included), another root
//     leaf's userdata, or a write by another root state
//   * output key: a key a selected state writes, or that userdata staying inside sets, that
//     another root state reads
//   * remapping: `{key: root key}` only for lifted userdata that was renamed; every other key
//     keeps its name (SMACH's default remapping is the identity)
// Lists keep the order in which the selected states first use the keys.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "refactor/contain_scope.h"
#include "refactor/contain_userdata.h"

namespace smachac::refactor {

struct KeyPlan {
  std::vector<std::string> input_keys;
  std::vector<std::string> output_keys;
  std::vector<std::pair<std::string, std::string>> remapping;
};

KeyPlan inferKeys(const ContainScope& scope, const UserdataPlan& userdata);

}  // namespace smachac::refactor
