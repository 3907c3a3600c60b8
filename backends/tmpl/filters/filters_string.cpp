// String filters: lower, upper, capitalize, title, trim, replace, indent, center, wordwrap,
// wordcount, truncate, format, string, escape/e, forceescape, safe, tojson.
#include <algorithm>
#include <cstring>

#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/filters/text_wrap.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/values/py_format.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

// Jinja's soft_str: strings unchanged (markup kept), anything else through str().
Value softStr(const Value& v) { return v.isString() ? v : Value::string(str(v)); }

// Whether lower-casing leaves `s` as it is: ASCII without capitals (most names and keys).
bool isPlainLower(std::string_view s) {
  return std::none_of(s.begin(), s.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x80 || (c >= 'A' && c <= 'Z');
  });
}

// A string that lower-casing leaves unchanged is returned itself, as indent returns its input.
Value lowerFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "lower", {});
  if (in.isString() && isPlainLower(in.s())) return in;
  return Value::string(unicode::toLower(softStr(in).s()), in.isMarkup());
}

Value upperFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "upper", {});
  return Value::string(unicode::toUpper(softStr(in).s()), in.isMarkup());
}

Value capitalizeFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "capitalize", {});
  return Value::string(unicode::capitalize(softStr(in).s()), in.isMarkup());
}

// Jinja's title: split before runs of `-`, whitespace, `(`, `{`, `[`, `<`; capitalise each piece.
Value titleFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "title", {});
  const std::string s = softStr(in).s();
  auto separator = [](char32_t c) {
    return c == '-' || c == '(' || c == '{' || c == '[' || c == '<' || unicode::isSpace(c);
  };
  std::string out;
  size_t pos = 0;
  while (pos < s.size()) {
    size_t start = pos;
    size_t next = pos;
    bool sep = separator(unicode::decode(s, next));
    while (pos < s.size()) {
      size_t probe = pos;
      if (separator(unicode::decode(s, probe)) != sep) break;
      pos = probe;
    }
    std::string_view piece(s.data() + start, pos - start);
    if (sep) {
      out += piece;
      continue;
    }
    size_t first_end = 0;
    unicode::decode(piece, first_end);
    out += unicode::toUpper(piece.substr(0, first_end));
    out += unicode::toLower(piece.substr(first_end));
  }
  return Value::string(std::move(out), in.isMarkup());
}

Value trimFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "trim", {"chars"});
  const Value* chars = b.get(0);
  const std::string* set = chars && !chars->isNone() ? &stringArg(*chars, "trim") : nullptr;
  return Value::string(stripString(softStr(in).s(), set, true, true));
}

Value replaceFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "replace", {"old", "new", "count"});
  int64_t count = b.has(2) && !b.get(2)->isNone() ? b.getInt(2, -1) : -1;
  return Value::string(replaceString(str(in), str(b.require(0)), str(b.require(1)), count));
}

// Jinja2's indent appended to `out`: the lines of `input + "\n"` (so that a final line break
// is kept) joined by "\n" and the indention (not before empty lines unless `blank`). The
// lines are walked in `input` itself: the added "\n" ends the last line, or after a final
// line break that is not a lone "\r" (with which it would form one "\r\n") it adds an empty
// line. The result, counted from where it starts in `out`, is a string within the limits.
void appendIndented(std::string& out, std::string_view input, std::string_view indention,
                    bool first, bool blank) {
  size_t start = out.size();
  size_t limit = activeLimits().string_bytes;  // checked after each line, as checkSize would
  if (first) out += indention;
  LineCursor cursor(input, false);
  bool first_line = true;
  auto add = [&](std::string_view line) {
    if (!first_line) {
      out += '\n';
      if (blank || !line.empty()) out += indention;
    }
    first_line = false;
    out += line;
    if (out.size() - start > limit) checkSize(out.size() - start, "string");
  };
  for (std::string_view line; cursor.next(line);) add(line);
  if (cursor.endedWithBreak() && input.back() != '\r') add({});
}

// The number of "\n" in `s`, 8 bytes a step (std::count took about 2.4 instructions a byte on
// the final render's bodies): a byte's lane of `lanes` counts its matches, up to 255 words.
size_t countLineFeeds(std::string_view s) {
  constexpr uint64_t kOnes = 0x0101010101010101ull;
  constexpr uint64_t kLow7 = kOnes * 0x7F;
  constexpr uint64_t kPairs = 0x00FF00FF00FF00FFull;
  size_t count = 0;
  size_t i = 0;
  while (s.size() - i >= 8) {
    uint64_t lanes = 0;
    for (size_t k = 0; k < 255 && s.size() - i >= 8; ++k, i += 8) {
      uint64_t word;
      std::memcpy(&word, s.data() + i, sizeof word);
      uint64_t x = word ^ (kOnes * '\n');            // a zero byte where "\n" was
      uint64_t nonzero = ((x & kLow7) + kLow7) | x;  // high bit: the byte is not zero
      lanes += (~nonzero >> 7) & kOnes;
    }
    uint64_t pairs = (lanes & kPairs) + ((lanes >> 8) & kPairs);  // four 16-bit sums
    count += static_cast<size_t>((pairs * 0x0001000100010001ull) >> 48);
  }
  for (; i < s.size(); ++i) count += s[i] == '\n';
  return count;
}

// The size of the result (exact but for the rarer line breaks than "\n").
size_t indentedSize(std::string_view input, std::string_view indention) {
  return input.size() + (countLineFeeds(input) + 2) * indention.size();
}

// indent's arguments; with a string input, which `indent` needs. A width of up to
// kSpaces.size() views a constant run of spaces instead of building the indention.
struct IndentCall {
  std::string_view view;  // the string argument, or a run of kSpaces
  std::string built;      // a longer run of spaces
  bool first = false;
  bool blank = false;
  std::string_view indention() const { return built.empty() ? view : std::string_view(built); }
};

const std::string_view kSpaces = "                                                                ";

IndentCall bindIndent(const Value& in, Args args) {
  ArgBinder b(args, "indent", {"width", "first", "blank"});
  IndentCall call;
  if (b.has(0) && b.get(0)->isString()) {
    call.view = b.get(0)->s();
  } else {
    int64_t width = b.getInt(0, 4);
    auto count = static_cast<size_t>(width);
    // checkSize fails exactly above the limit: called only then (it compares its kind's name).
    if (width > 0 && count > activeLimits().string_bytes) checkSize(count, "string");
    if (width > 0 && count <= kSpaces.size()) {
      call.view = kSpaces.substr(0, count);
    } else if (width > 0) {
      call.built.assign(count, ' ');
    }
  }
  if (!in.isString()) {
    if (in.isUndefined()) fail(in.undefinedMessage());
    fail("`indent` expects a string, not `" + std::string(typeName(in)) + "`");
  }
  call.first = b.getBool(1, false);
  call.blank = b.getBool(2, false);
  return call;
}

// Whether indent returns its input unchanged: one line, and no indention before it.
bool indentKeepsInput(bool one_line, const IndentCall& call) {
  return one_line && (!call.first || call.indention().empty());
}

// indent's result appended to `out`, reserved first (`reserve` gets the size to add);
// `one_line`: the input has no line break.
template <class Reserve>
void appendIndentResult(std::string& out, const std::string& input, bool one_line,
                        const IndentCall& call, Reserve reserve) {
  if (one_line) {  // only `first` changes it
    std::string_view prefix = call.first ? call.indention() : std::string_view();
    reserve(prefix.size() + input.size());
    out.append(prefix).append(input);
    return;
  }
  reserve(indentedSize(input, call.indention()));
  appendIndented(out, input, call.indention(), call.first, call.blank);
}

Value indentFilter(Exec&, const Value& in, Args args) {
  IndentCall call = bindIndent(in, args);
  bool one_line = !mayHaveLineBreak(in.s());
  if (indentKeepsInput(one_line, call)) return in;
  std::string out;
  appendIndentResult(out, in.s(), one_line, call, [&](size_t size) { out.reserve(size); });
  return Value::string(std::move(out), in.isMarkup());
}

// `{{ text | indent(n) }}` written straight into the output, without the indented copy beside
// it (on a large generated body, the copy is the render's peak). It is charged as the string
// value of indentFilter would have been.
bool indentInto(Exec&, const Value& in, Args args, std::string& out) {
  IndentCall call = bindIndent(in, args);
  bool one_line = !mayHaveLineBreak(in.s());
  bool keeps_input = indentKeepsInput(one_line, call);
  size_t start = out.size();
  appendIndentResult(out, in.s(), one_line, call, [&](size_t size) { reserveToAppend(out, size); });
  if (!keeps_input) chargeWork(out.size() - start);
  return true;
}

Value centerFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "center", {"width"});
  return Value::string(centerString(softStr(in).s(), b.getInt(0, 80), " "));
}

Value wordwrapFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "wordwrap", {"width", "break_long_words", "wrapstring", "break_on_hyphens"});
  int64_t width = b.getInt(0, 79);
  bool break_long = b.getBool(1, true);
  std::string wrapstring = b.has(2) && !b.get(2)->isNone() ? str(*b.get(2)) : "\n";
  bool hyphens = b.getBool(3, true);
  std::string out;
  std::vector<std::string> paragraphs = splitLines(stringArg(in, "wordwrap"), false);
  for (size_t i = 0; i < paragraphs.size(); ++i) {
    if (i > 0) out += wrapstring;
    std::vector<std::string> lines = wrapText(paragraphs[i], width, break_long, hyphens);
    for (size_t j = 0; j < lines.size(); ++j) {
      if (j > 0) out += wrapstring;
      out += lines[j];
    }
    checkSize(out.size(), "string");
  }
  return Value::string(std::move(out));
}

Value wordcountFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "wordcount", {});
  std::string s = str(in);
  int64_t words = 0;
  bool in_word = false;
  for (size_t pos = 0; pos < s.size();) {
    char32_t c = unicode::decode(s, pos);
    bool word = c == '_' || unicode::isAlnum(c);
    if (word && !in_word) ++words;
    in_word = word;
  }
  return Value::integer(words);
}

Value truncateFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "truncate", {"length", "killwords", "end", "leeway"});
  std::string s = stringArg(in, "truncate");
  int64_t length = b.getInt(0, 255);
  std::string end = b.has(2) ? str(*b.get(2)) : "...";
  int64_t leeway = b.has(3) && !b.get(3)->isNone() ? b.getInt(3, 5) : 5;
  auto end_len = static_cast<int64_t>(unicode::length(end));
  if (length < end_len)
    fail("expected length >= " + std::to_string(end_len) + ", got " + std::to_string(length));
  if (leeway < 0) fail("expected leeway >= 0, got " + std::to_string(leeway));
  std::vector<Value> chars = iterate(Value::string(s));
  if (static_cast<int64_t>(chars.size()) <= length + leeway) return Value::string(s);
  std::string head;
  for (int64_t i = 0; i < length - end_len; ++i) head += chars[static_cast<size_t>(i)].s();
  if (b.getBool(1, false)) return Value::string(head + end);
  size_t space = head.rfind(' ');
  return Value::string((space == std::string::npos ? head : head.substr(0, space)) + end);
}

Value formatFilter(Exec&, const Value& in, Args args) {
  if (!args.positional.empty() && !args.keyword.empty()) {
    fail("`format` cannot handle positional and keyword arguments at the same time");
  }
  Value fmt = softStr(in);
  if (!args.keyword.empty()) {
    Value kwargs = Value::newDict();
    for (const auto& [k, v] : args.keyword) kwargs.dict().setString(*k, v);
    return percentFormat(fmt, kwargs);
  }
  return percentFormat(fmt, Value::newTuple({args.positional.begin(), args.positional.end()}));
}

Value stringFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "string", {});
  return softStr(in);
}

Value escapeFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "escape", {});
  if (in.isMarkup()) return in;
  return Value::string(htmlEscape(str(in)), true);
}

Value forceescapeFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "forceescape", {});
  return Value::string(htmlEscape(str(in)), true);
}

Value safeFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "safe", {});
  return Value::string(str(in), true);
}

Value tojsonFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "tojson", {"indent"});
  int64_t indent = b.has(0) && !b.get(0)->isNone() ? b.getInt(0, 0) : -1;
  return Value::string(toJson(in, indent), true);
}

}  // namespace

void registerStringFilters(BuiltinTable& r) {
  r.addFilter("lower", lowerFilter);
  r.addFilter("upper", upperFilter);
  r.addFilter("capitalize", capitalizeFilter);
  r.addFilter("title", titleFilter);
  r.addFilter("trim", trimFilter);
  r.addFilter("replace", replaceFilter);
  r.addFilter("indent", indentFilter, indentInto);
  r.addFilter("center", centerFilter);
  r.addFilter("wordwrap", wordwrapFilter);
  r.addFilter("wordcount", wordcountFilter);
  r.addFilter("truncate", truncateFilter);
  r.addFilter("format", formatFilter);
  r.addFilter("string", stringFilter);
  r.addFilter("e", escapeFilter);
  r.addFilter("escape", escapeFilter);
  r.addFilter("forceescape", forceescapeFilter);
  r.addFilter("safe", safeFilter);
  r.addFilter("tojson", tojsonFilter);
}

}  // namespace smachac::tmpl
