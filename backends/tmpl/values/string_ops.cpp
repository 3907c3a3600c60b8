// Python str methods and helpers (see string_ops.h), the stable sort, and dict views.
#include "backends/tmpl/values/string_ops.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/py_format.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

std::vector<char32_t> codePoints(std::string_view s) {
  std::vector<char32_t> out;
  for (size_t pos = 0; pos < s.size();) out.push_back(unicode::decode(s, pos));
  return out;
}

std::string encodeAll(const std::vector<char32_t>& cps, size_t begin, size_t end) {
  std::string out;
  for (size_t i = begin; i < end; ++i) unicode::encode(out, cps[i]);
  return out;
}

int64_t cpIndex(std::string_view s, size_t bytes) {
  return static_cast<int64_t>(unicode::length(s.substr(0, bytes)));
}

bool allChars(std::string_view s, bool (*pred)(char32_t)) {
  if (s.empty()) return false;
  for (size_t pos = 0; pos < s.size();) {
    if (!pred(unicode::decode(s, pos))) return false;
  }
  return true;
}

bool isDigitChar(char32_t c) { return c >= '0' && c <= '9'; }
bool isAlphaChar(char32_t c) { return unicode::isAlnum(c) && !isDigitChar(c); }

// str.islower / str.isupper: at least one cased character and no cased one of the other case.
bool caseCheck(std::string_view s, bool lower) {
  bool cased = false;
  for (size_t pos = 0; pos < s.size();) {
    char32_t c = unicode::decode(s, pos);
    if (unicode::isTitle(c) || (lower ? unicode::isUpper(c) : unicode::isLower(c))) return false;
    if (lower ? unicode::isLower(c) : unicode::isUpper(c)) cased = true;
  }
  return cased;
}

bool affixMatch(std::string_view s, const Value& affix, bool prefix) {
  auto test = [&](const Value& a) {
    const std::string& t = stringArg(a, prefix ? "startswith" : "endswith");
    if (t.size() > s.size()) return false;
    return prefix ? s.substr(0, t.size()) == t : s.substr(s.size() - t.size()) == t;
  };
  if (affix.isTuple()) {
    return std::any_of(affix.list().items().begin(), affix.list().items().end(), test);
  }
  return test(affix);
}

std::string pad(std::string_view s, int64_t width, std::string_view fill, char align) {
  int64_t len = static_cast<int64_t>(unicode::length(s));
  if (width <= len) return std::string(s);
  checkSize(static_cast<size_t>(width) * fill.size(), "string");
  auto missing = static_cast<size_t>(width - len);
  size_t left = align == '<'   ? 0
                : align == '>' ? missing
                               : missing / 2 + (missing & static_cast<size_t>(width) & 1);
  std::string out;
  for (size_t i = 0; i < left; ++i) out += fill;
  out += s;
  for (size_t i = left; i < missing; ++i) out += fill;
  return out;
}

std::string_view fillArg(const CallArgs& args, std::string_view method) {
  if (args.positional.size() < 2) return " ";
  const std::string& fill = stringArg(args.positional[1], method);
  if (unicode::length(fill) != 1) fail("the fill character must be exactly one character long");
  return fill;
}

const Value& need(const CallArgs& args, size_t i, std::string_view method) {
  if (i >= args.positional.size()) {
    fail("`" + std::string(method) + "` expects at least " + std::to_string(i + 1) +
         " argument(s)");
  }
  return args.positional[i];
}

Value listOf(std::vector<std::string> parts) {
  std::vector<Value> items;
  items.reserve(parts.size());
  for (std::string& p : parts) items.push_back(Value::string(std::move(p)));
  return Value::newList(std::move(items));
}

int64_t intArg(const CallArgs& args, size_t i, int64_t fallback) {
  if (i >= args.positional.size() || args.positional[i].isNone()) return fallback;
  const Value& v = args.positional[i];
  if (!v.isInt() && !v.isBool())
    fail("an integer is required, not `" + std::string(typeName(v)) + "`");
  return v.integral();
}

Value joinStrings(const Value& sep, const Value& iterable) {
  std::string out;
  size_t i = 0;
  for (const Value& item : iterate(iterable)) {
    if (!item.isString()) {
      fail("sequence item " + std::to_string(i) + ": expected str instance, `" +
           std::string(typeName(item)) + "` found");
    }
    if (i++ > 0) out += sep.s();
    out += item.s();
    checkSize(out.size(), "string");
  }
  return Value::string(std::move(out));
}

Value searchMethod(std::string_view s, std::string_view name, const CallArgs& args) {
  const std::string& sub = stringArg(need(args, 0, name), name);
  if (name == "count") {
    if (sub.empty()) return Value::integer(static_cast<int64_t>(unicode::length(s)) + 1);
    int64_t n = 0;
    for (size_t pos = s.find(sub); pos != std::string_view::npos;
         pos = s.find(sub, pos + sub.size()))
      ++n;
    return Value::integer(n);
  }
  size_t pos = name == "rfind" ? s.rfind(sub) : s.find(sub);
  if (pos == std::string_view::npos) {
    if (name == "index") fail("substring not found");
    return Value::integer(-1);
  }
  return Value::integer(cpIndex(s, pos));
}

}  // namespace

const std::string& stringArg(const Value& v, std::string_view what) {
  if (v.isString()) return v.s();
  if (v.isUndefined()) fail(v.undefinedMessage());
  fail("`" + std::string(what) + "` expects a string, not `" + std::string(typeName(v)) + "`");
}

std::string replaceString(std::string_view s, std::string_view old, std::string_view with,
                          int64_t count) {
  std::string out;
  if (old.empty()) {
    std::vector<char32_t> cps = codePoints(s);
    for (size_t i = 0; i <= cps.size(); ++i) {
      if (count < 0 || static_cast<int64_t>(i) < count) out += with;
      if (i < cps.size()) unicode::encode(out, cps[i]);
      checkSize(out.size(), "string");
    }
    return out;
  }
  size_t start = 0;
  for (int64_t n = 0; count < 0 || n < count; ++n) {
    size_t pos = s.find(old, start);
    if (pos == std::string_view::npos) break;
    out.append(s.substr(start, pos - start));
    out.append(with);
    checkSize(out.size(), "string");
    start = pos + old.size();
  }
  out.append(s.substr(start));
  return out;
}

std::vector<std::string> splitString(std::string_view s, const std::string* sep, int64_t maxsplit,
                                     bool from_right) {
  std::vector<std::string> parts;
  if (sep) {
    if (sep->empty()) fail("empty separator");
    if (!from_right) {
      size_t start = 0;
      for (size_t pos = s.find(*sep);
           pos != std::string_view::npos &&
           (maxsplit < 0 || static_cast<int64_t>(parts.size()) < maxsplit);
           pos = s.find(*sep, start)) {
        parts.emplace_back(s.substr(start, pos - start));
        start = pos + sep->size();
      }
      parts.emplace_back(s.substr(start));
      return parts;
    }
    size_t end = s.size();
    while (maxsplit < 0 || static_cast<int64_t>(parts.size()) < maxsplit) {
      if (end < sep->size()) break;
      size_t pos = s.rfind(*sep, end - sep->size());
      if (pos == std::string_view::npos) break;
      parts.emplace_back(s.substr(pos + sep->size(), end - pos - sep->size()));
      end = pos;
    }
    parts.emplace_back(s.substr(0, end));
    std::reverse(parts.begin(), parts.end());
    return parts;
  }
  std::vector<char32_t> cps = codePoints(s);
  std::vector<std::pair<size_t, size_t>> words;
  for (size_t i = 0; i < cps.size();) {
    while (i < cps.size() && unicode::isSpace(cps[i])) ++i;
    size_t j = i;
    while (j < cps.size() && !unicode::isSpace(cps[j])) ++j;
    if (j > i) words.emplace_back(i, j);
    i = j;
  }
  if (maxsplit < 0 || static_cast<int64_t>(words.size()) <= maxsplit + 1) {
    for (auto [a, b] : words) parts.push_back(encodeAll(cps, a, b));
    return parts;
  }
  auto keep = static_cast<size_t>(maxsplit);
  if (!from_right) {
    for (size_t i = 0; i < keep; ++i)
      parts.push_back(encodeAll(cps, words[i].first, words[i].second));
    size_t rest_end = cps.size();
    while (rest_end > words[keep].first && unicode::isSpace(cps[rest_end - 1])) --rest_end;
    parts.push_back(encodeAll(cps, words[keep].first, rest_end));
    return parts;
  }
  size_t first = words.size() - keep;
  size_t rest_begin = 0;
  while (rest_begin < cps.size() && unicode::isSpace(cps[rest_begin])) ++rest_begin;
  parts.push_back(encodeAll(cps, rest_begin, words[first - 1].second));
  for (size_t i = first; i < words.size(); ++i)
    parts.push_back(encodeAll(cps, words[i].first, words[i].second));
  return parts;
}

namespace {

// Bytes that can start a line break (Python's str.splitlines): \n \v \f \r, \x1c-\x1e, and
// the lead bytes of U+0085 and U+2028/U+2029.
struct LineBreakLeads {
  bool table[256] = {};
  constexpr LineBreakLeads() {
    for (unsigned char c : {'\n', '\v', '\f', '\r', '\x1c', '\x1d', '\x1e'}) table[c] = true;
    table[0xC2] = table[0xE2] = true;
  }
};
constexpr LineBreakLeads kLineBreakLeads;

// The high bit of each of the 8 bytes at `p` that is below 0x20 or above 0x7F (printable ASCII
// cannot start a line break), the lowest set bit in the first such byte (bytes after it may be
// marked wrongly by the borrow); 0 when all 8 are printable ASCII.
uint64_t nonPlainBytes(const char* p) {
  uint64_t word = 0;
  std::memcpy(&word, p, sizeof word);
  constexpr uint64_t kOnes = 0x0101010101010101ull;
  constexpr uint64_t kHigh = 0x8080808080808080ull;
  uint64_t below_space = (word - kOnes * 0x20) & ~word & kHigh;
  return (below_space | word) & kHigh;
}

// The length of the line break starting at byte `i` of `s`, or 0.
size_t breakLength(std::string_view s, size_t i) {
  auto c = static_cast<unsigned char>(s[i]);
  if (c == '\n' || c == '\v' || c == '\f' || (c >= 0x1C && c <= 0x1E)) return 1;
  if (c == '\r') return i + 1 < s.size() && s[i + 1] == '\n' ? 2 : 1;
  if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0x85) {
    return 2;  // U+0085
  }
  if (c == 0xE2 && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0x80 &&
      (static_cast<unsigned char>(s[i + 2]) & 0xFE) == 0xA8) {
    return 3;  // U+2028, U+2029
  }
  return 0;
}

}  // namespace

bool LineCursor::next(std::string_view& line) {
  size_t i = start_;
  while (i < s_.size()) {
    if (s_.size() - i >= 8) {  // most of a line: 8 bytes a step, then to its first other byte
      uint64_t marks = nonPlainBytes(s_.data() + i);
      if (marks == 0) {
        i += 8;
        continue;
      }
      // The lowest marked byte comes first in memory on a little-endian machine only.
      if constexpr (std::endian::native == std::endian::little) {
        i += static_cast<size_t>(std::countr_zero(marks)) / 8;
      }
    }
    for (size_t stop = std::min(s_.size(), i + 8); i < stop; ++i) {
      size_t length =
          kLineBreakLeads.table[static_cast<unsigned char>(s_[i])] ? breakLength(s_, i) : 0;
      if (length == 0) continue;
      line = s_.substr(start_, (keepends_ ? i + length : i) - start_);
      start_ = i + length;
      ended_with_break_ = start_ == s_.size();
      return true;
    }
  }
  if (start_ >= s_.size()) return false;
  line = s_.substr(start_);
  start_ = s_.size();
  return true;
}

std::vector<std::string_view> lineViews(std::string_view s, bool keepends) {
  std::vector<std::string_view> lines;
  LineCursor cursor(s, keepends);
  for (std::string_view line; cursor.next(line);) lines.push_back(line);
  return lines;
}

bool mayHaveLineBreak(std::string_view s) {
  return std::any_of(s.begin(), s.end(),
                     [](char c) { return kLineBreakLeads.table[static_cast<unsigned char>(c)]; });
}

std::vector<std::string> splitLines(std::string_view s, bool keepends) {
  std::vector<std::string> lines;
  for (std::string_view line : lineViews(s, keepends)) lines.emplace_back(line);
  return lines;
}

std::string stripString(std::string_view s, const std::string* chars, bool left, bool right) {
  if (!chars) return std::string(unicode::strip(s, left, right));
  std::vector<char32_t> set = codePoints(*chars);
  std::vector<char32_t> cps = codePoints(s);
  auto in_set = [&](char32_t c) { return std::find(set.begin(), set.end(), c) != set.end(); };
  size_t begin = 0;
  size_t end = cps.size();
  while (left && begin < end && in_set(cps[begin])) ++begin;
  while (right && end > begin && in_set(cps[end - 1])) --end;
  return encodeAll(cps, begin, end);
}

std::string centerString(std::string_view s, int64_t width, std::string_view fill) {
  return pad(s, width, fill, '^');
}

Value stringMethod(const Value& self, std::string_view name, const CallArgs& args) {
  const std::string& s = self.s();
  if (name == "format") {
    Value kwargs = Value::newDict();
    for (const auto& [k, v] : args.keyword) kwargs.dict().setString(*k, v);
    return braceFormat(self, {args.positional.begin(), args.positional.end()}, &kwargs.dict());
  }
  if (!args.keyword.empty()) fail("`" + std::string(name) + "` takes no keyword arguments");
  auto opt_string = [&](size_t i) -> const std::string* {
    if (i >= args.positional.size() || args.positional[i].isNone()) return nullptr;
    return &stringArg(args.positional[i], name);
  };
  if (name == "lower") return Value::string(unicode::toLower(s));
  if (name == "upper") return Value::string(unicode::toUpper(s));
  if (name == "capitalize") return Value::string(unicode::capitalize(s));
  if (name == "title") return Value::string(unicode::title(s));
  if (name == "swapcase") return Value::string(unicode::swapcase(s));
  if (name == "strip") return Value::string(stripString(s, opt_string(0), true, true));
  if (name == "lstrip") return Value::string(stripString(s, opt_string(0), true, false));
  if (name == "rstrip") return Value::string(stripString(s, opt_string(0), false, true));
  if (name == "startswith") return Value::boolean(affixMatch(s, need(args, 0, name), true));
  if (name == "endswith") return Value::boolean(affixMatch(s, need(args, 0, name), false));
  if (name == "replace") {
    return Value::string(replaceString(s, stringArg(need(args, 0, name), name),
                                       stringArg(need(args, 1, name), name), intArg(args, 2, -1)));
  }
  if (name == "split" || name == "rsplit") {
    return listOf(splitString(s, opt_string(0), intArg(args, 1, -1), name == "rsplit"));
  }
  if (name == "splitlines") {
    return listOf(splitLines(s, !args.positional.empty() && truthy(args.positional[0])));
  }
  if (name == "join") return joinStrings(self, need(args, 0, name));
  if (name == "count" || name == "find" || name == "rfind" || name == "index") {
    return searchMethod(s, name, args);
  }
  if (name == "isdigit") return Value::boolean(allChars(s, isDigitChar));
  if (name == "isalpha") return Value::boolean(allChars(s, isAlphaChar));
  if (name == "isalnum") return Value::boolean(allChars(s, unicode::isAlnum));
  if (name == "isspace") return Value::boolean(allChars(s, unicode::isSpace));
  if (name == "islower") return Value::boolean(caseCheck(s, true));
  if (name == "isupper") return Value::boolean(caseCheck(s, false));
  need(args, 0, name);
  int64_t width = intArg(args, 0, 0);
  if (name == "center") return Value::string(pad(s, width, fillArg(args, name), '^'));
  if (name == "ljust") return Value::string(pad(s, width, fillArg(args, name), '<'));
  if (name == "rjust") return Value::string(pad(s, width, fillArg(args, name), '>'));
  // zfill
  bool sign = !s.empty() && (s[0] == '-' || s[0] == '+');
  std::string digits =
      pad(std::string_view(s).substr(sign ? 1 : 0), width - (sign ? 1 : 0), "0", '>');
  return Value::string((sign ? s.substr(0, 1) : "") + digits);
}

namespace {

// A stable merge sort that stays in bounds whatever the comparison results.
template <class Before>
void mergeSort(std::vector<size_t>& order, Before before) {
  size_t n = order.size();
  for (size_t i = 1; i < n && n <= 16; ++i) {  // insertion sort for short inputs
    size_t v = order[i];
    size_t j = i;
    for (; j > 0 && before(v, order[j - 1]); --j) order[j] = order[j - 1];
    order[j] = v;
  }
  if (n <= 16) return;
  std::vector<size_t> buffer(n);
  for (size_t width = 1; width < n; width *= 2) {
    for (size_t lo = 0; lo < n; lo += 2 * width) {
      size_t mid = std::min(lo + width, n);
      size_t hi = std::min(lo + 2 * width, n);
      size_t i = lo, j = mid, o = lo;
      while (i < mid && j < hi) buffer[o++] = before(order[j], order[i]) ? order[j++] : order[i++];
      while (i < mid) buffer[o++] = order[i++];
      while (j < hi) buffer[o++] = order[j++];
    }
    order.swap(buffer);
  }
}

}  // namespace

std::vector<Value> sortValues(std::vector<Value> items, bool reverse,
                              const std::vector<Value>* keys) {
  std::vector<size_t> order(items.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  const std::vector<Value>& k = keys ? *keys : items;
  mergeSort(order, [&](size_t a, size_t b) {
    return reverse ? lessThan(k[b], k[a]) : lessThan(k[a], k[b]);
  });
  std::vector<Value> out;
  out.reserve(items.size());
  for (size_t i : order) out.push_back(std::move(items[i]));
  return out;
}

// Tuple comparison (sequenceLess) of the pairs (ka, va) and (kb, vb). Two different str keys
// (the common case) decide it by their bytes, which order as their code points.
bool pairLess(const DictObject::Entry& a, const DictObject::Entry& b) {
  if (a.first.isString() && b.first.isString()) {
    int order = a.first.s().compare(b.first.s());
    if (order != 0) return order < 0;
  }
  DepthGuard guard;
  if (!(a.first.identity() && a.first.identity() == b.first.identity()) &&
      !equals(a.first, b.first)) {
    return lessThan(a.first, b.first);
  }
  if (!(a.second.identity() && a.second.identity() == b.second.identity()) &&
      !equals(a.second, b.second)) {
    return lessThan(a.second, b.second);
  }
  return false;
}

std::vector<size_t> sortedItemsOrder(const DictObject& dict) {
  const std::vector<DictObject::Entry>& entries = dict.entries();
  std::vector<size_t> order(entries.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  mergeSort(order, [&](size_t a, size_t b) { return pairLess(entries[a], entries[b]); });
  return order;
}

namespace {

class DictViewObject final : public Object {
 public:
  DictViewObject(Value dict, DictView kind) : dict_(std::move(dict)), kind_(kind) {}
  std::string_view typeName() const override {
    return kind_ == DictView::Items  ? "dict_items"
           : kind_ == DictView::Keys ? "dict_keys"
                                     : "dict_values";
  }
  bool iterate(std::vector<Value>& out) const override {
    for (const auto& [k, v] : dict_.dict().entries()) {
      if (kind_ == DictView::Items) out.push_back(Value::newTuple({k, v}));
      if (kind_ == DictView::Keys) out.push_back(k);
      if (kind_ == DictView::Values) out.push_back(v);
    }
    return true;
  }
  void repr(std::string& out) const override {
    std::vector<Value> items;
    iterate(items);
    out += typeName();
    out += "(";
    appendRepr(out, Value::newList(std::move(items)));
    out += ")";
  }

 private:
  Value dict_;
  DictView kind_;
};

}  // namespace

Value makeDictView(const Value& dict, DictView kind) {
  return Value::object(new DictViewObject(dict, kind));
}

}  // namespace smachac::tmpl
