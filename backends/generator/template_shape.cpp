// Template outlines from source text, and the shapes of template chains.
#include "backends/generator/template_shape.h"

#include <cctype>

namespace smachac::generator {
namespace {

enum class TokenKind { Text, Output, Statement, Comment, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  ///< text, or a tag's inside without delimiters and markers
};

/// Splits template source into text, `{{ }}`, `{% %}` and `{# #}` (quotes respected in tags).
class Scanner {
 public:
  explicit Scanner(std::string_view source) : s_(source) {}

  Token next() {
    if (pos_ >= s_.size()) return {};
    size_t open = findOpen(pos_);
    if (open != pos_) {
      Token t{TokenKind::Text, s_.substr(pos_, open - pos_)};
      pos_ = open;
      return t;
    }
    char kind = s_[pos_ + 1];
    if (kind == '#') return comment();
    size_t close = findClose(pos_ + 2, kind == '{' ? '}' : '%');
    if (close == std::string_view::npos) return fail();
    Token t{kind == '{' ? TokenKind::Output : TokenKind::Statement,
            trimMarkers(s_.substr(pos_ + 2, close - pos_ - 2))};
    pos_ = close + 2;
    return t;
  }

  bool failed() const { return failed_; }

 private:
  size_t findOpen(size_t from) const {
    for (size_t i = from; i + 1 < s_.size(); ++i) {
      if (s_[i] == '{' && (s_[i + 1] == '{' || s_[i + 1] == '%' || s_[i + 1] == '#')) return i;
    }
    return s_.size();
  }

  /// The position of the closing `}}` / `%}`, skipping quoted strings.
  size_t findClose(size_t from, char first) const {
    char quote = 0;
    for (size_t i = from; i + 1 < s_.size(); ++i) {
      char c = s_[i];
      if (quote) {
        if (c == '\\')
          ++i;
        else if (c == quote)
          quote = 0;
      } else if (c == '\'' || c == '"') {
        quote = c;
      } else if (c == first && s_[i + 1] == '}') {
        return i;
      }
    }
    return std::string_view::npos;
  }

  Token comment() {
    size_t close = s_.find("#}", pos_ + 2);
    if (close == std::string_view::npos) return fail();
    pos_ = close + 2;
    return {TokenKind::Comment, {}};
  }

  Token fail() {
    failed_ = true;
    pos_ = s_.size();
    return {};
  }

  static std::string_view trimMarkers(std::string_view t) {
    if (!t.empty() && (t.front() == '-' || t.front() == '+')) t.remove_prefix(1);
    if (!t.empty() && (t.back() == '-' || t.back() == '+')) t.remove_suffix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    return t;
  }

  std::string_view s_;
  size_t pos_ = 0;
  bool failed_ = false;
};

bool blank(std::string_view text) {
  for (char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

/// The first word of a tag and the rest.
std::pair<std::string_view, std::string_view> split(std::string_view tag) {
  size_t end = 0;
  while (end < tag.size() &&
         (std::isalnum(static_cast<unsigned char>(tag[end])) || tag[end] == '_')) {
    ++end;
  }
  std::string_view rest = tag.substr(end);
  while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.front()))) {
    rest.remove_prefix(1);
  }
  return {tag.substr(0, end), rest};
}

/// A string literal that is the whole argument, without its quotes.
std::optional<std::string> literal(std::string_view arg) {
  if (arg.size() < 2 || (arg.front() != '"' && arg.front() != '\'') || arg.back() != arg.front()) {
    return std::nullopt;
  }
  std::string_view inner = arg.substr(1, arg.size() - 2);
  if (inner.find_first_of("\\'\"") != std::string_view::npos) return std::nullopt;
  return std::string(inner);
}

/// Outlines the body of a block up to its `endblock`: blank or not; false when the body is
/// outside the simple subset (a nested block or raw text) or has no end.
bool blockBody(Scanner& scanner, bool& is_blank) {
  is_blank = true;
  for (Token t = scanner.next(); t.kind != TokenKind::End; t = scanner.next()) {
    if (t.kind == TokenKind::Comment) continue;
    if (t.kind == TokenKind::Text) {
      is_blank = is_blank && blank(t.text);
      continue;
    }
    if (t.kind == TokenKind::Output) {
      is_blank = false;
      continue;
    }
    std::string_view word = split(t.text).first;
    if (word == "endblock") return true;
    if (word == "block" || word == "raw") return false;
    is_blank = false;
  }
  return false;
}

/// Skips a top-level macro definition up to its `endmacro`.
bool macroBody(Scanner& scanner) {
  for (Token t = scanner.next(); t.kind != TokenKind::End; t = scanner.next()) {
    if (t.kind != TokenKind::Statement) continue;
    std::string_view word = split(t.text).first;
    if (word == "endmacro") return true;
    if (word == "macro" || word == "block" || word == "raw") return false;
  }
  return false;
}

/// One top-level statement; false when it is outside the simple subset.
bool topLevelStatement(Scanner& scanner, std::string_view tag, TemplateOutline& out) {
  auto [word, rest] = split(tag);
  if (word == "from" || word == "import") return true;
  if (word == "set") {
    out.has_set_or_macro = true;
    return rest.find('=') != std::string_view::npos;  // not a block set
  }
  if (word == "macro") {
    out.has_set_or_macro = true;
    return macroBody(scanner);
  }
  if (word == "extends") {
    out.parent = literal(rest);
    return out.parent.has_value();
  }
  if (word == "block") {
    std::string name(split(rest).first);
    bool is_blank = true;
    if (name.empty() || out.blocks.count(name) || !blockBody(scanner, is_blank)) return false;
    out.blocks[name] = is_blank;
    return true;
  }
  return false;
}

}  // namespace

TemplateOutline outlineTemplate(std::string_view source) {
  TemplateOutline out;
  Scanner scanner(source);
  for (Token t = scanner.next(); t.kind != TokenKind::End; t = scanner.next()) {
    bool ok = t.kind == TokenKind::Comment || (t.kind == TokenKind::Text && blank(t.text)) ||
              (t.kind == TokenKind::Statement && topLevelStatement(scanner, t.text, out));
    if (!ok) return TemplateOutline{};
  }
  out.simple = !scanner.failed();
  return out;
}

bool TemplateShape::rendersEmpty(const std::string& block) const {
  if (!layout.count(block)) return true;
  auto it = blank.find(block);
  return it != blank.end() && it->second;
}

const std::optional<TemplateShape>& TemplateShapes::shape(const std::string& name) {
  auto it = shapes_.find(name);
  if (it == shapes_.end()) it = shapes_.emplace(name, analyze(name)).first;
  return it->second;
}

std::optional<std::vector<TemplateOutline>> TemplateShapes::chain(const std::string& name) {
  constexpr size_t kMaxDepth = 32;
  std::vector<TemplateOutline> outlines;
  std::optional<std::string> next = name;
  while (next) {
    std::optional<std::string> source = readTemplateSource(path_, *next);
    if (!source || outlines.size() >= kMaxDepth) return std::nullopt;
    outlines.push_back(outlineTemplate(*source));
    if (!outlines.back().simple) return std::nullopt;
    next = outlines.back().parent;
  }
  return outlines;
}

std::optional<TemplateShape> TemplateShapes::analyze(const std::string& name) {
  std::optional<std::vector<TemplateOutline>> outlines = chain(name);
  if (!outlines) return std::nullopt;
  TemplateShape shape;
  shape.may_export = false;
  for (const auto& [block, is_blank] : outlines->back().blocks) shape.layout.insert(block);
  for (const TemplateOutline& outline : *outlines) {  // most derived first: it wins
    shape.may_export = shape.may_export || outline.has_set_or_macro;
    for (const auto& [block, is_blank] : outline.blocks) shape.blank.emplace(block, is_blank);
  }
  return shape;
}

}  // namespace smachac::generator
