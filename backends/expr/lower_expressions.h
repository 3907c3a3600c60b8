// Portable expressions become target code: before a code target renders its templates, every
// `!expr` callback is replaced by backtick code of the target's language (python_lambda.h for
// smach and flexbe, cpp_lambda.h for cpp), which the templates write like any callback the
// script gave as code. Other targets (ir, json, dot) show the expressions as written.
#pragma once

#include <string_view>

#include "ir/module.h"

namespace smachac::backends::expr {

void lowerPortableExpressions(ir::Module& module, std::string_view target);

}  // namespace smachac::backends::expr
