// A portable expression as a C++ callback of the smachac runtime:
// `[](rt::UserData& ud) -> rt::Value { return <expression>; }`. Every operand is an rt::Value
// (input keys read with `ud.at("key", position)`, literals and params as Values), every operator a
// call of rt::ops (stdlib/runtime: expression_ops.h), which computes what Python computes; `and`
// and `or` evaluate their right side only when it decides, as Python does.
#pragma once

#include <string>

#include "ir/expr.h"
#include "ir/state.h"

namespace smachac::backends::expr {

std::string cppLambda(const ir::PortableExpr& expr, const ir::State& state);

}  // namespace smachac::backends::expr
