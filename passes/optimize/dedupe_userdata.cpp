// dedupe-userdata: removes `userdata` entries that set a key to the value it already has.
// When a container is built, its own entries are applied first, then each leaf child's in
// order (passes/analysis/userdata_scope.h); an entry equal (ir::sameValue) to the key's value
// at that point changes nothing.
//
//   before                                      after
//   base SEQ  userdata: {speed: 0.5}            base SEQ  userdata: {speed: 0.5}
//     leaf A  userdata: {speed: 0.5, tool: x}     leaf A  userdata: {tool: x}
//     leaf B  userdata: {tool: x}                 leaf B
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "passes/optimize/transforms.h"

namespace smachac::passes {
namespace {

using Values = std::unordered_map<std::string, ir::Value>;

/// Drops the entries of `userdata` that `current` already has; records the others.
bool dedupe(std::vector<ir::Argument>& userdata, Values& current) {
  std::vector<ir::Argument> kept;
  for (ir::Argument& entry : userdata) {
    auto it = current.find(entry.key.text);
    if (it != current.end() && ir::sameValue(it->second, entry.value)) continue;
    current.insert_or_assign(entry.key.text, entry.value);
    kept.push_back(std::move(entry));
  }
  bool changed = kept.size() != userdata.size();
  userdata = std::move(kept);
  return changed;
}

bool dedupeScope(ir::Module& module, ir::StateId id) {
  Values current;
  bool changed = dedupe(module.state(id).userdata, current);
  for (ir::StateId id_child : module.state(id).children) {
    ir::State& child = module.state(id_child);
    if (!ir::isContainer(child.kind)) changed = dedupe(child.userdata, current) || changed;
  }
  return changed;
}

}  // namespace

bool dedupeUserdata(ir::Module& module, PassContext&) {
  bool changed = false;
  for (ir::StateId id : module.preorder()) {
    if (ir::isContainer(module.state(id).kind)) changed = dedupeScope(module, id) || changed;
  }
  return changed;
}

}  // namespace smachac::passes
