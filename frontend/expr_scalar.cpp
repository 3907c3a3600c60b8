// Locating and parsing `!expr` scalars.
#include "frontend/expr_scalar.h"

#include "frontend/expr_parser.h"

namespace smachac::frontend {

size_t ExprScalarReader::offsetOf(int line, int column) {
  if (line < cached_line_) cached_line_ = 0, cached_offset_ = 0;
  while (cached_line_ < line) {
    size_t next = document_.find('\n', cached_offset_);
    if (next == std::string_view::npos) return document_.size();
    cached_offset_ = next + 1;
    ++cached_line_;
  }
  return std::min(cached_offset_ + static_cast<size_t>(column), document_.size());
}

size_t ExprScalarReader::textOffset(size_t tag_offset, std::string_view value) const {
  if (document_.substr(tag_offset, kPortableExprTag.size()) != kPortableExprTag) {
    return std::string_view::npos;
  }
  size_t at = tag_offset + kPortableExprTag.size();
  while (at < document_.size() && document_[at] == ' ') ++at;
  if (at < document_.size() && (document_[at] == '\'' || document_[at] == '"')) ++at;
  if (document_.substr(at, value.size()) != value) return std::string_view::npos;
  if (value.find('\n') != std::string_view::npos) return std::string_view::npos;
  return at;
}

ir::Value ExprScalarReader::read(int line, int column, std::string_view value,
                                 std::optional<ExprScalarError>& error) {
  SourceLoc tag{file_, static_cast<uint32_t>(line + 1), static_cast<uint32_t>(column + 1),
                static_cast<uint32_t>(kPortableExprTag.size())};
  size_t text = line < 0 ? std::string_view::npos : textOffset(offsetOf(line, column), value);
  uint32_t text_column = text == std::string_view::npos
                             ? 0
                             : static_cast<uint32_t>(column + 1 + (text - offsetOf(line, column)));
  ExprLocator locate = [&](uint32_t offset, uint32_t length) {
    if (text_column == 0) return tag;
    return SourceLoc{file_, tag.line, text_column + offset, length};
  };
  auto parsed = parseExpr(value, locate);
  if (auto* failure = std::get_if<ExprSyntaxError>(&parsed)) {
    error = ExprScalarError{locate(failure->offset, failure->length), failure->message};
    return ir::Value::null(tag);
  }
  SourceLoc whole = text_column == 0 ? tag : locate(0, static_cast<uint32_t>(value.size()));
  return ir::Value::portable(std::get<std::shared_ptr<const ir::PortableExpr>>(parsed), whole);
}

}  // namespace smachac::frontend
