// Python str operations shared by the str methods and the string filters.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "backends/tmpl/renderer/call_args.h"
#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

/// Calls Python str method `name` on `self` (a string).
Value stringMethod(const Value& self, std::string_view name, const CallArgs& args);

std::string replaceString(std::string_view s, std::string_view old, std::string_view with,
                          int64_t count);
/// str.split(): on runs of whitespace when `sep` is null; at most `maxsplit` splits (-1: all).
std::vector<std::string> splitString(std::string_view s, const std::string* sep, int64_t maxsplit,
                                     bool from_right = false);
/// str.splitlines(keepends).
std::vector<std::string> splitLines(std::string_view s, bool keepends);
/// str.splitlines(keepends) as views into `s`.
std::vector<std::string_view> lineViews(std::string_view s, bool keepends);

/// str.splitlines(keepends) one line at a time, as views into the text (lineViews without
/// holding every line at once).
class LineCursor {
 public:
  LineCursor(std::string_view s, bool keepends) : s_(s), keepends_(keepends) {}
  /// The next line, or false when there is none left.
  bool next(std::string_view& line);
  /// After the last line: whether a line break ended the text.
  bool endedWithBreak() const { return ended_with_break_; }

 private:
  std::string_view s_;
  bool keepends_;
  size_t start_ = 0;
  bool ended_with_break_ = false;
};
/// Makes room in `out` for `extra` more bytes. A large addition gets an eighth of headroom
/// instead of std::string's doubling at the next append: an output that ends in one large
/// piece (a rendered body and a few lines after it) then holds about its size, not twice it.
inline void reserveToAppend(std::string& out, size_t extra) {
  constexpr size_t kLargeAddition = size_t{1} << 20;
  size_t needed = out.size() + extra;
  if (extra >= kLargeAddition && needed > out.capacity()) out.reserve(needed + needed / 8);
}
/// False when `s` certainly has a single line (no byte that can start a line break).
bool mayHaveLineBreak(std::string_view s);
/// str.strip(chars): whitespace when `chars` is null.
std::string stripString(std::string_view s, const std::string* chars, bool left, bool right);
/// str.center(width, fill).
std::string centerString(std::string_view s, int64_t width, std::string_view fill);
/// The argument as a str, or Fault naming what was expected.
const std::string& stringArg(const Value& v, std::string_view what);

/// A stable sort of `items` by Python ordering (`reverse` keeps equal items in order).
std::vector<Value> sortValues(std::vector<Value> items, bool reverse,
                              const std::vector<Value>* keys = nullptr);
/// The order in which `d.items() | sort` puts the entries of `dict`: the order of the sorted
/// (key, value) tuples, with the same comparisons (and the same faults), without the tuples.
std::vector<size_t> sortedItemsOrder(const DictObject& dict);

enum class DictView { Items, Keys, Values };
Value makeDictView(const Value& dict, DictView kind);

}  // namespace smachac::tmpl
