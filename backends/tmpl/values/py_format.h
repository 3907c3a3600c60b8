// Python string formatting: printf-style `fmt % args` (also the `format` filter) and the
// str.format() method with the format-spec mini-language for str, int and float.
#pragma once

#include <vector>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

/// `fmt % args`: args is a tuple of values, a dict for %(name)s, or a single value.
Value percentFormat(const Value& fmt, const Value& args);

/// `fmt.format(*args, **kwargs)`; `kwargs` may be null.
Value braceFormat(const Value& fmt, const std::vector<Value>& args, const DictObject* kwargs);

}  // namespace smachac::tmpl
