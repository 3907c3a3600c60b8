// A portable expression as a Python callback: `lambda ud: <expression>`, input keys read as
// `ud.<key>`, params written as Python literals. The expression language is Python's syntax,
// so the expression keeps its shape; only names and literals are rewritten.
#pragma once

#include <string>

#include "ir/expr.h"
#include "ir/state.h"

namespace smachac::backends::expr {

std::string pythonLambda(const ir::PortableExpr& expr, const ir::State& state);

}  // namespace smachac::backends::expr
