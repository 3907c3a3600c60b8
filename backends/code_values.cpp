// forEachCode (code_values.h).
#include "backends/code_values.h"

#include <variant>

namespace smachac::backends {
namespace {

void visitValue(const ir::Value& value, const std::string& what, const std::string& state,
                const std::function<void(const CodeSite&)>& visit) {
  if (value.kind() == ir::ValueKind::Expression) {
    visit(CodeSite{value, what, state});
  } else if (value.isList()) {
    for (const ir::Value& item : std::get<ir::List>(value.data))
      visitValue(item, what, state, visit);
  } else if (value.isMap()) {
    for (const ir::MapEntry& entry : std::get<ir::Map>(value.data)) {
      visitValue(entry.value, what, state, visit);
    }
  }
}

}  // namespace

void forEachCode(const ir::Module& module, const std::function<void(const CodeSite&)>& visit) {
  for (ir::StateId id : module.preorder()) {
    const ir::State& state = module.state(id);
    for (const ir::Argument& callback : state.callbacks) {
      visitValue(callback.value, "callback `" + callback.key.text + "`", state.name.text, visit);
    }
    for (const ir::Argument& entry : state.userdata) {
      visitValue(entry.value, "userdata `" + entry.key.text + "`", state.name.text, visit);
    }
    for (const ir::Argument& argument : state.args) {
      visitValue(argument.value, "`" + argument.key.text + "`", state.name.text, visit);
    }
  }
}

}  // namespace smachac::backends
