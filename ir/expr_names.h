// What a name in a portable expression stands for in its state: one of the state's input keys
// (read from the userdata when the callback runs) or, failing that, one of its params (whose
// value is written into the expression).
#pragma once

#include <string_view>

#include "ir/state.h"

namespace smachac::ir {

enum class ExprNameKind : uint8_t { InputKey, Param, Unknown };

struct ExprName {
  ExprNameKind kind = ExprNameKind::Unknown;
  const Name* key = nullptr;     ///< the input key, for ExprNameKind::InputKey
  const Value* param = nullptr;  ///< the param's value, for ExprNameKind::Param
};

ExprName bindExprName(const State& state, std::string_view name);

}  // namespace smachac::ir
