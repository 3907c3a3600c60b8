// Deferred macros. A built-in template like smach/Utils.tpl.py is a library of two dozen
// macros of which one compile calls a few, so the parser may leave the signature and body of
// a top-level macro unparsed (Template::completeMacro parses them on the macro's first call).
// It does so only where parsing later changes nothing the template shows before that call:
// the tokens reach the body's `endmacro`; the body has no `block`, `extends`, `include`,
// `import` or `from` tag (those are recorded template-wide: blocks, references,
// has_extends, names_templates); and every filter and test it names is registered (the
// parser's one error on text that lexes and nests). A macro that fails any of these is parsed
// at once, as before.
#include "backends/tmpl/parser/parser.h"

namespace smachac::tmpl {
namespace {

bool recordedTemplateWide(std::string_view tag) {
  return tag == "block" || tag == "extends" || tag == "include" || tag == "import" || tag == "from";
}

}  // namespace

// Called after a macro's name, at its signature: the signature is deferred with the body (its
// default values are expressions like any other). On success the parser stands after the
// body's `endmacro`, where the statement loop expects the closing `%}`.
bool Parser::deferMacro(MacroStmt* macro) {
  if (!defer_macros_ || tag_stack_.size() != 1 || !current().is(Tok::LParen)) return false;
  std::optional<size_t> end = deferrableBodyEnd(index_);
  if (!end) return false;
  macro->deferred = true;
  result_.deferred.push_back({macro, index_, {}, {}});
  index_ = *end + 1;
  return true;
}

// The index of the body's `endmacro` name, or nullopt if the macro must be parsed now; the
// scan starts at the signature (which has no tags, so the first tag it meets is the body's).
std::optional<size_t> Parser::deferrableBodyEnd(size_t first) const {
  int depth = 0;
  for (size_t i = first; i + 1 < tokens_.size(); ++i) {
    const Token& token = tokens_[i];
    switch (token.kind) {
      case Tok::Pipe:
        if (!knownFilterOrTestAt(i)) return std::nullopt;
        continue;
      case Tok::Name:
        if (token.length == 2 && isName(token, "is") && !knownFilterOrTestAt(i)) {
          return std::nullopt;
        }
        continue;
      case Tok::BlockBegin:
        break;
      default:
        continue;
    }
    if (!tokens_[i + 1].is(Tok::Name)) continue;
    std::string_view tag = textOf(tokens_[i + 1]);
    if (recordedTemplateWide(tag)) return std::nullopt;
    if (tag == "filter" && !knownFilterOrTestAt(i + 1)) return std::nullopt;
    if (tag == "macro") ++depth;
    if (tag == "endmacro" && depth-- == 0) return i + 1;
  }
  return std::nullopt;
}

// At `|` or `{% filter` (the filter name follows) or `is` (`not` may come first): whether
// the name is a plain name the registry knows.
bool Parser::knownFilterOrTestAt(size_t index) const {
  bool test = isName(tokens_[index], "is");
  size_t name_index = index + 1;
  if (test && isName(tokens_[name_index], "not")) ++name_index;
  if (name_index + 1 >= tokens_.size()) return false;
  const Token& token = tokens_[name_index];
  if (!token.is(Tok::Name) || tokens_[name_index + 1].is(Tok::Dot)) return false;
  return test ? registry_.test(textOf(token)) != nullptr
              : registry_.filter(textOf(token)) != nullptr;
}

// The signature and body, in the same state as parseMacro's eager parse: inside the `macro`
// tag at nesting 1.
void Parser::parseDeferredMacro(const DeferredMacro& deferred) {
  MacroStmt* macro = deferred.macro;
  index_ = deferred.first_token;
  NestingGuard guard(*this, macro->pos);
  tag_stack_.push_back({"macro", macro->pos});
  parseSignature(macro);
  macro->body = parseStatements({"endmacro"}, EndTag::Keep);
  tag_stack_.pop_back();
}

}  // namespace smachac::tmpl
