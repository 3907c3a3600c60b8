// Whether a piece of backtick code is a Python expression: the grammar of Python 3's
// expressions (what `ast.parse(code, mode="eval")` accepts), from lambdas and conditional
// expressions down to literals, comprehensions and calls. The code is only recognised, not
// interpreted: names are not resolved and f-string fields are not parsed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace smachac::backends {

/// Why code is not a Python expression: what went wrong, at which byte of the code.
struct PythonSyntaxError {
  size_t offset = 0;
  std::string message;  ///< e.g. "unexpected `)`", "unterminated string"
};

/// Nothing for a Python expression, else the first syntax error.
std::optional<PythonSyntaxError> pythonExpressionError(std::string_view code);

}  // namespace smachac::backends
