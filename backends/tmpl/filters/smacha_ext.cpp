// SMACHA's custom tests and filter:
//   exptostr   — on each line, removes the first and the last backtick (re.sub('`(.*)`', r'\1'))
//   expression — re.match('`.*`$', value): a one-line string wrapped in backticks
//   not_string — true for lists, dicts, numbers (bools included), strings Python's float()
//                accepts, dotted words (fullmatch (\w+[.])+\w+) and calls (.+\(.*\)$)
#include <optional>

#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/values/py_number.h"
#include "backends/tmpl/values/value_ops.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

const std::string& requireString(const Value& v, std::string_view what) {
  if (v.isString()) return v.s();
  if (v.isUndefined()) fail(v.undefinedMessage());
  fail("`" + std::string(what) + "` expects a string, not `" + std::string(typeName(v)) + "`");
}

Value exptostrFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "exptostr", {});
  const std::string& s = requireString(in, "exptostr");
  std::string out;
  size_t start = 0;
  while (start <= s.size()) {
    size_t end = s.find('\n', start);
    std::string_view line(s.data() + start, (end == std::string::npos ? s.size() : end) - start);
    size_t first = line.find('`');
    size_t last = line.rfind('`');
    if (first != std::string_view::npos && last != first) {
      out.append(line.substr(0, first));
      out.append(line.substr(first + 1, last - first - 1));
      out.append(line.substr(last + 1));
    } else {
      out.append(line);
    }
    if (end == std::string::npos) break;
    out.push_back('\n');
    start = end + 1;
  }
  return Value::string(std::move(out));
}

// The first line of `s` when `s` is that line, optionally followed by one final newline
// (where Python's `$` matches); nullopt otherwise.
std::optional<std::string_view> singleLine(std::string_view s) {
  size_t newline = s.find('\n');
  if (newline == std::string_view::npos) return s;
  if (newline + 1 == s.size()) return s.substr(0, newline);
  return std::nullopt;
}

bool expressionTest(Exec&, const Value& v, Args args) {
  ArgBinder(args, "expression", {});
  auto line = singleLine(requireString(v, "expression"));
  return line && line->size() >= 2 && line->front() == '`' && line->back() == '`';
}

bool isWordChar(char32_t c) { return c == '_' || unicode::isAlnum(c); }

// fullmatch((\w+[.])+\w+): two or more non-empty runs of word characters joined by dots.
bool dottedWords(std::string_view s) {
  size_t parts = 0;
  size_t run = 0;
  for (size_t pos = 0; pos < s.size();) {
    char32_t c = unicode::decode(s, pos);
    if (c == '.') {
      if (run == 0) return false;
      ++parts;
      run = 0;
    } else if (isWordChar(c)) {
      ++run;
    } else {
      return false;
    }
  }
  return parts >= 1 && run > 0;
}

// re.match(.+\(.*\)$): on one line, ends with `)` and has a `(` after the first character.
bool looksLikeCall(std::string_view s) {
  auto line = singleLine(s);
  if (!line || line->size() < 3 || line->back() != ')') return false;
  size_t first_end = 0;
  unicode::decode(*line, first_end);
  size_t open = line->find('(', first_end);
  return open != std::string_view::npos && open + 1 < line->size();
}

bool notStringTest(Exec&, const Value& v, Args args) {
  ArgBinder(args, "not_string", {});
  if (v.isListOrTuple() || v.isDict() || v.isNumber()) return v.isTuple() ? false : true;
  if (!v.isString()) return false;
  double ignored;
  return parsePythonFloat(v.s(), ignored) || dottedWords(v.s()) || looksLikeCall(v.s());
}

}  // namespace

void registerSmachaExtensions(BuiltinTable& r) {
  r.addFilter("exptostr", exptostrFilter);
  r.addTest("expression", expressionTest);
  r.addTest("not_string", notStringTest);
}

}  // namespace smachac::tmpl
