// Tokens of portable expressions (`!expr`, ir/expr.h): numbers as Python writes them (`12`,
// `1.5`, `.5`, `1e-3`), strings in single or double quotes with Python's common escapes (\\ \'
// \" \n \t \r \0 \xHH \uHHHH), names, the operators and parentheses. Offsets count bytes from
// the start of the expression.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/value.h"

namespace smachac::frontend {

enum class ExprTokenKind : uint8_t { Number, String, Name, Operator, End };

struct ExprToken {
  ExprTokenKind kind = ExprTokenKind::End;
  uint32_t offset = 0;
  uint32_t length = 0;
  std::string_view text;  ///< as written
  ir::Value value;        ///< Number: an int or float; String: the decoded string
};

/// A problem at a place in the expression.
struct ExprSyntaxError {
  std::string message;
  uint32_t offset = 0;
  uint32_t length = 1;
};

struct ExprTokens {
  /// Ends with an End token: at the end of the text, or where the lexical error is.
  std::vector<ExprToken> tokens;
  std::optional<ExprSyntaxError> error;  ///< the first lexical error
};

ExprTokens lexExpr(std::string_view text);

}  // namespace smachac::frontend
