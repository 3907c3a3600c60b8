// Every piece of backtick code of a module, with what it is: the one walk of the checks of
// target code (foreign_lambdas.h, python_code_check.h).
#pragma once

#include <functional>
#include <string>

#include "ir/module.h"

namespace smachac::backends {

/// Where a backtick value stands: `what` ("userdata `n`", "callback `n`", "`time`") of the
/// state named `state`.
struct CodeSite {
  const ir::Value& value;
  std::string what;
  const std::string& state;
};

/// Calls `visit` for every backtick value in the callbacks, userdata and template variables
/// of every state (in that order, states in preorder), lists and maps included.
void forEachCode(const ir::Module& module, const std::function<void(const CodeSite&)>& visit);

}  // namespace smachac::backends
