// The parser of portable expressions (`!expr`): text → ir::PortableExpr, by recursive descent
// over the grammar of ir/expr.h, one function per grammar rule.
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <variant>

#include "frontend/expr_lexer.h"
#include "ir/expr.h"

namespace smachac::frontend {

/// The script location of `length` bytes at `offset` in the expression text.
using ExprLocator = std::function<SourceLoc(uint32_t offset, uint32_t length)>;

std::variant<std::shared_ptr<const ir::PortableExpr>, ExprSyntaxError> parseExpr(
    std::string_view text, const ExprLocator& locate);

}  // namespace smachac::frontend
