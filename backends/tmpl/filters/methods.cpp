// Python methods of built-in values that templates call: str (lower, split, format, ...),
// list (append, extend, pop, ...), dict (items, get, update, setdefault, and the Python 2
// iteritems/iterkeys/itervalues aliases SMACHA's templates use) and tuple.
#include <algorithm>
#include <string_view>

#include "backends/tmpl/error.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/py_format.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

constexpr std::string_view kStringMethods[] = {
    "capitalize", "center",  "count",    "endswith", "find",    "format", "index", "isalnum",
    "isalpha",    "isdigit", "islower",  "isspace",  "isupper", "join",   "ljust", "lower",
    "lstrip",     "replace", "rfind",    "rjust",    "rsplit",  "rstrip", "split", "splitlines",
    "startswith", "strip",   "swapcase", "title",    "upper",   "zfill",
};
constexpr std::string_view kListMethods[] = {"append", "clear",   "copy",   "count",
                                             "extend", "index",   "insert", "pop",
                                             "remove", "reverse", "sort"};
constexpr std::string_view kTupleMethods[] = {"count", "index"};
constexpr std::string_view kDictMethods[] = {"clear",     "copy",       "get",        "items",
                                             "iteritems", "iterkeys",   "itervalues", "keys",
                                             "pop",       "setdefault", "update",     "values"};

template <size_t N>
bool contains(const std::string_view (&names)[N], std::string_view name) {
  return std::find(std::begin(names), std::end(names), name) != std::end(names);
}

const Value& arg(Args args, size_t i, std::string_view method);

int64_t intArg(Args args, size_t i, std::string_view method) {
  const Value& v = arg(args, i, method);
  if (v.isInt() || v.isBool()) return v.integral();
  fail("`" + std::string(method) + "` expects an integer, not `" + std::string(typeName(v)) + "`");
}

const Value& arg(Args args, size_t i, std::string_view method) {
  if (i >= args.positional.size()) {
    fail("`" + std::string(method) + "` expects at least " + std::to_string(i + 1) +
         " argument(s)");
  }
  return args.positional[i];
}

void noKeywords(Args args, std::string_view method) {
  if (!args.keyword.empty()) fail("`" + std::string(method) + "` takes no keyword arguments");
}

Value listMethod(const Value& self, std::string_view name, Args args) {
  auto& items = self.list().items();
  noKeywords(args, name);
  if (name == "append") {
    checkSize(items.size() + 1, "list");
    items.push_back(arg(args, 0, name));
  } else if (name == "extend") {
    std::vector<Value> more = iterate(arg(args, 0, name));
    checkSize(items.size() + more.size(), "list");
    items.insert(items.end(), more.begin(), more.end());
  } else if (name == "pop") {
    if (items.empty()) fail("pop from empty list");
    int64_t n = static_cast<int64_t>(items.size());
    int64_t i = args.positional.empty() ? n - 1 : intArg(args, 0, name);
    if (i < 0) i += n;
    if (i < 0 || i >= n) fail("pop index out of range");
    Value out = items[static_cast<size_t>(i)];
    items.erase(items.begin() + i);
    return out;
  } else if (name == "insert") {
    int64_t n = static_cast<int64_t>(items.size());
    int64_t i = intArg(args, 0, name);
    i = i < 0 ? std::max<int64_t>(0, i + n) : std::min(i, n);
    items.insert(items.begin() + i, arg(args, 1, name));
  } else if (name == "remove") {
    auto it = std::find_if(items.begin(), items.end(),
                           [&](const Value& v) { return equals(v, arg(args, 0, name)); });
    if (it == items.end()) fail("list.remove(x): x not in list");
    items.erase(it);
  } else if (name == "clear") {
    items.clear();
  } else if (name == "copy") {
    return Value::newList(items);
  } else if (name == "reverse") {
    std::reverse(items.begin(), items.end());
  } else if (name == "sort") {
    std::vector<Value> sorted = sortValues(items, false);
    items = std::move(sorted);
  } else {
    return Value::undefined();
  }
  return Value::none();
}

Value sequenceLookup(const Value& self, std::string_view name, Args args) {
  const auto& items = self.list().items();
  const Value& needle = arg(args, 0, name);
  if (name == "count") {
    return Value::integer(std::count_if(items.begin(), items.end(),
                                        [&](const Value& v) { return equals(v, needle); }));
  }
  for (size_t i = 0; i < items.size(); ++i) {
    if (equals(items[i], needle)) return Value::integer(static_cast<int64_t>(i));
  }
  fail("value is not in the " + std::string(typeName(self)));
}

Value dictMethod(const Value& self, std::string_view name, Args args) {
  DictObject& d = self.dict();
  if (name == "items" || name == "iteritems") return makeDictView(self, DictView::Items);
  if (name == "keys" || name == "iterkeys") return makeDictView(self, DictView::Keys);
  if (name == "values" || name == "itervalues") return makeDictView(self, DictView::Values);
  if (name == "get") {
    const Value* v = d.find(arg(args, 0, name));
    return v ? *v : args.positional.size() > 1 ? args.positional[1] : Value::none();
  }
  if (name == "setdefault") {
    const Value& key = arg(args, 0, name);
    if (const Value* v = d.find(key)) return *v;
    Value fallback = args.positional.size() > 1 ? args.positional[1] : Value::none();
    d.set(key, fallback);
    return fallback;
  }
  if (name == "pop") {
    Value removed;
    if (d.erase(arg(args, 0, name), &removed)) return removed;
    if (args.positional.size() > 1) return args.positional[1];
    fail("key " + repr(arg(args, 0, name)) + " not found");
  }
  if (name == "update") {
    if (!args.positional.empty()) {
      const Value& other = args.positional[0];
      if (other.isDict()) {
        for (const auto& [k, v] : other.dict().entries()) d.set(k, v);
      } else {
        for (const Value& pair : iterate(other)) {
          std::vector<Value> kv = iterate(pair);
          if (kv.size() != 2) fail("dictionary update sequence element has the wrong length");
          d.set(kv[0], kv[1]);
        }
      }
    }
    for (const auto& [k, v] : args.keyword) d.setString(*k, v);
    return Value::none();
  }
  if (name == "copy") {
    Value copy = Value::newDict();
    for (const auto& [k, v] : d.entries()) copy.dict().set(k, v);
    return copy;
  }
  d.clear();
  return Value::none();
}

}  // namespace

bool hasMethod(const Value& self, std::string_view name) {
  switch (self.kind()) {
    case Kind::String:
      return contains(kStringMethods, name);
    case Kind::List:
      return contains(kListMethods, name);
    case Kind::Tuple:
      return contains(kTupleMethods, name);
    case Kind::Dict:
      return contains(kDictMethods, name);
    default:
      return false;
  }
}

bool callMethod(Exec& ex, const Value& self, std::string_view name, const CallArgs& args,
                Value& out) {
  if (self.isObject()) {
    Value fn;
    if (!self.object()->getAttr(name, fn)) return false;
    out = callValue(ex, fn, args);
    return true;
  }
  if (!hasMethod(self, name)) return false;
  switch (self.kind()) {
    case Kind::String:
      out = stringMethod(self, name, args);
      return true;
    case Kind::List:
      if (name == "count" || name == "index") {
        out = sequenceLookup(self, name, args);
      } else {
        out = listMethod(self, name, args);
      }
      return true;
    case Kind::Tuple:
      out = sequenceLookup(self, name, args);
      return true;
    case Kind::Dict:
      out = dictMethod(self, name, args);
      return true;
    default:
      return false;
  }
}

}  // namespace smachac::tmpl
