// Python's tokens, as far as an expression needs them: names and keywords, numbers, strings
// (with their prefixes, triple quotes and adjacent pieces), operators and brackets. Line breaks
// inside brackets, backslash continuations and comments are skipped, as Python's tokenizer
// skips them; a line break outside brackets ends the expression.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::backends {

enum class PythonTokenKind { Name, Keyword, Number, String, Operator, End };

struct PythonToken {
  PythonTokenKind kind = PythonTokenKind::End;
  std::string_view text;
  size_t offset = 0;  ///< byte offset in the code
};

struct PythonTokenError {
  size_t offset = 0;
  std::string message;
};

/// The tokens of `code`, ending with an End token; or the first lexical error.
struct PythonTokens {
  std::vector<PythonToken> tokens;
  std::optional<PythonTokenError> error;
};

PythonTokens tokenizePython(std::string_view code);

}  // namespace smachac::backends
