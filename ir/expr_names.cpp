// Name binding of portable expressions.
#include "ir/expr_names.h"

namespace smachac::ir {

ExprName bindExprName(const State& state, std::string_view name) {
  for (const Name& key : state.input_keys) {
    if (key.text == name) return {ExprNameKind::InputKey, &key, nullptr};
  }
  if (state.params) {
    if (const Value* param = state.params->find(name)) return {ExprNameKind::Param, nullptr, param};
  }
  return {};
}

}  // namespace smachac::ir
