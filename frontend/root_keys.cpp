// Script root keys.
#include "frontend/root_keys.h"

#include <string>

#include "frontend/state_builder.h"
#include "ir/support/suggest.h"

namespace smachac::frontend {
namespace {

const std::vector<std::string>& knownRootKeys() {
  // import_modules and from_imports: the imports a ROS script declares (templates/smach_ros).
  static const std::vector<std::string> kKeys = {
      "name",      "template",      "outcomes", "states",         "userdata",    "manifest",
      "node_name", "function_name", "params",   "import_modules", "from_imports"};
  return kKeys;
}

bool isKnown(const std::string& key) {
  for (const std::string& k : knownRootKeys()) {
    if (k == key) return true;
  }
  return false;
}

}  // namespace

bool buildRootState(const ir::Value& root, ir::State& state, DiagnosticEmitter& diags) {
  state.kind = ir::StateKind::Base;
  state.loc = root.loc;
  ir::Value typed = ir::Value::map({}, root.loc);
  for (const ir::MapEntry& e : root.asMap()) {
    if (e.key == "name") {
      readName(e.value, "the script's `name`", state.name, diags);
    } else if (e.key == "states") {
      continue;  // lowered state by state; copying it would copy the whole script
    } else if (isKnown(e.key)) {
      typed.asMap().push_back(e);
    } else {
      std::optional<std::string> match = closestMatch(e.key, knownRootKeys());
      diags.emit<DiagKind::UnknownRootKey>(e.key_loc, e.key, didYouMean(match));
      diags.fixIt(match);
    }
  }
  buildStateFields(typed, state, "the script", diags);
  bool complete = true;
  for (const char* key : {"name", "template", "states"}) {
    if (!root.find(key)) {
      diags.emit<DiagKind::MissingKey>(root.loc, "the script", key);
      complete = false;
    }
  }
  return complete;
}

}  // namespace smachac::frontend
