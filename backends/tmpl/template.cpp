// Template compilation: normalise, tokenise, parse, analyse scopes.
#include "backends/tmpl/template.h"

#include "backends/tmpl/ast/scope.h"
#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/parser/parser.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {

Template::Template(std::string name, std::string origin, std::string_view source,
                   const Registry& registry)
    : name_(std::move(name)), origin_(std::move(origin)), source_(normalizeSource(source)) {
  try {
    std::vector<Token> tokens = tokenize(source_);
    ParsedTemplate parsed = parseTemplate(source_, tokens, registry, arena_);
    analyzeScopes(parsed, root_frame_);
    body_ = std::move(parsed.body);
    blocks_ = std::move(parsed.blocks);
    references_ = std::move(parsed.references);
    has_extends_ = parsed.has_extends;
  } catch (const SyntaxFault& fault) {
    throw error(fault.pos, fault.message);
  }
}

const BlockStmt* Template::block(std::string_view name) const {
  for (const BlockStmt* b : blocks_) {
    if (*b->name == name) return b;
  }
  return nullptr;
}

std::pair<int, int> Template::lineColumn(uint32_t pos) const {
  if (pos > source_.size()) pos = static_cast<uint32_t>(source_.size());
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < pos; ++i) {
    if (source_[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  int column = 1 + static_cast<int>(unicode::length(
                       std::string_view(source_).substr(line_start, pos - line_start)));
  return {line, column};
}

TemplateError Template::error(uint32_t pos, std::string message) const {
  auto [line, column] = lineColumn(pos);
  return TemplateError(origin_, line, column, std::move(message));
}

}  // namespace smachac::tmpl
