// Python's str() and repr() of IR values, as SMACHA's string constructs and templates print
// them: True/False/None, floats via repr, lists and dicts in repr form with quoted strings.
#pragma once

#include <string>
#include <string_view>

#include "ir/value.h"

namespace smachac::ir {

std::string pythonStr(const Value& value);
std::string pythonRepr(const Value& value);

}  // namespace smachac::ir
