// Sequence filters: join, sort, dictsort, unique, min, max, sum, default/d, length/count,
// first, last, list, items, reverse, attr.
#include <algorithm>

#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/attr_path.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

Value joinFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "join", {"d", "attribute"});
  std::string converted;  // a separator that is not a string, as str() prints it
  if (b.has(0) && !b.get(0)->isString()) converted = str(*b.get(0));
  std::string_view sep = b.has(0) && b.get(0)->isString() ? b.get(0)->s() : converted;
  AttrPath path(b.get(1, Value::none()));
  std::string out;
  bool first = true;
  auto join = [&](const std::vector<Value>& items) {
    for (const Value& item : items) {
      if (!first) out += sep;
      first = false;
      appendStr(out, path.get(item));
      checkSize(out.size(), "string");
    }
  };
  // Printing runs no template code, so a list can be read in place instead of copied.
  if (in.isListOrTuple()) {
    join(in.list().items());
  } else {
    join(iterate(in));
  }
  return Value::string(std::move(out));
}

Value sortFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "sort", {"reverse", "case_sensitive", "attribute"});
  std::vector<Value> items = iterate(in);
  bool any_string =
      std::any_of(items.begin(), items.end(), [](const Value& v) { return v.isString(); });
  if (!b.has(2) && !any_string) {  // each item is its own key (the pairs of `items()`)
    return Value::newList(sortValues(std::move(items), b.getBool(0, false), nullptr));
  }
  std::vector<AttrPath> paths = multiAttrPath(b.get(2, Value::none()));
  bool case_sensitive = b.getBool(1, false);
  std::vector<Value> keys;
  keys.reserve(items.size());
  for (const Value& item : items) {
    if (paths.size() == 1) {  // a one-element key list orders like its element
      Value k = paths[0].get(item);
      keys.push_back(case_sensitive ? k : ignoreCase(k));
      continue;
    }
    std::vector<Value> key;
    for (const AttrPath& path : paths) {
      Value k = path.get(item);
      key.push_back(case_sensitive ? k : ignoreCase(k));
    }
    keys.push_back(Value::newList(std::move(key)));
  }
  return Value::newList(sortValues(std::move(items), b.getBool(0, false), &keys));
}

Value dictsortFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "dictsort", {"case_sensitive", "by", "reverse"});
  std::string by = b.has(1) ? str(*b.get(1)) : "key";
  if (by != "key" && by != "value") fail("you can only sort by either `key` or `value`");
  if (!in.isDict()) fail("`dictsort` expects a dict, not `" + std::string(typeName(in)) + "`");
  std::vector<Value> items;
  std::vector<Value> keys;
  for (const auto& [k, v] : in.dict().entries()) {
    items.push_back(Value::newTuple({k, v}));
    const Value& key = by == "key" ? k : v;
    keys.push_back(b.getBool(0, false) ? key : ignoreCase(key));
  }
  return Value::newList(sortValues(std::move(items), b.getBool(2, false), &keys));
}

Value uniqueFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "unique", {"case_sensitive", "attribute"});
  AttrPath path(b.get(1, Value::none()));
  bool case_sensitive = b.getBool(0, false);
  Value seen = Value::newDict();
  std::vector<Value> out;
  for (const Value& item : iterate(in)) {
    Value key = path.get(item);
    if (!case_sensitive) key = ignoreCase(key);
    if (seen.dict().find(key)) continue;
    seen.dict().set(key, Value::none());
    out.push_back(item);
  }
  return Value::newList(std::move(out));
}

Value minMax(const Value& in, Args args, bool max) {
  ArgBinder b(args, max ? "max" : "min", {"case_sensitive", "attribute"});
  std::vector<Value> items = iterate(in);
  if (items.empty()) return Value::undefinedHint("no aggregated item, sequence was empty");
  AttrPath path(b.get(1, Value::none()));
  bool case_sensitive = b.getBool(0, false);
  auto key = [&](const Value& item) {
    Value k = path.get(item);
    return case_sensitive ? k : ignoreCase(k);
  };
  size_t best = 0;
  Value best_key = key(items[0]);
  for (size_t i = 1; i < items.size(); ++i) {
    Value k = key(items[i]);
    if (max ? lessThan(best_key, k) : lessThan(k, best_key)) {
      best = i;
      best_key = k;
    }
  }
  return items[best];
}

Value minFilter(Exec&, const Value& in, Args args) { return minMax(in, args, false); }
Value maxFilter(Exec&, const Value& in, Args args) { return minMax(in, args, true); }

Value sumFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "sum", {"attribute", "start"});
  AttrPath path(b.get(0, Value::none()));
  Value total = b.get(1, Value::integer(0));
  for (const Value& item : iterate(in)) total = binary(BinOp::Add, total, path.get(item));
  return total;
}

Value defaultFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "default", {"default_value", "boolean"});
  if (in.isUndefined() || (b.getBool(1, false) && !truthy(in))) {
    return b.get(0, Value::string(""));
  }
  return in;
}

Value lengthFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "length", {});
  return Value::integer(length(in));
}

Value firstFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "first", {});
  std::vector<Value> items = iterate(in);
  if (items.empty()) return Value::undefinedHint("no first item, sequence was empty");
  return items.front();
}

Value lastFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "last", {});
  std::vector<Value> items = iterate(in);
  if (items.empty()) return Value::undefinedHint("no last item, sequence was empty");
  return items.back();
}

Value listFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "list", {});
  return Value::newList(iterate(in));
}

Value itemsFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "items", {});
  if (in.isUndefined()) return Value::newList();
  if (!in.isDict()) fail("can only get item pairs from a mapping");
  std::vector<Value> out;
  for (const auto& [k, v] : in.dict().entries()) out.push_back(Value::newTuple({k, v}));
  return Value::newList(std::move(out));
}

Value reverseFilter(Exec&, const Value& in, Args args) {
  ArgBinder(args, "reverse", {});
  std::vector<Value> items = iterate(in);
  std::reverse(items.begin(), items.end());
  if (!in.isString()) return Value::newList(std::move(items));
  std::string out;
  for (const Value& c : items) out += c.s();
  return Value::string(std::move(out), in.isMarkup());
}

Value attrFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "attr", {"name"});
  const std::string& name = stringArg(b.require(0), "attr");
  if (in.isDict() && !hasMethod(in, name)) return Value::undefinedAttribute(in, intern(name));
  return getAttribute(in, intern(name));
}

}  // namespace

void registerSequenceFilters(BuiltinTable& r) {
  r.addFilter("join", joinFilter);
  r.addFilter("sort", sortFilter);
  r.addFilter("dictsort", dictsortFilter);
  r.addFilter("unique", uniqueFilter);
  r.addFilter("min", minFilter);
  r.addFilter("max", maxFilter);
  r.addFilter("sum", sumFilter);
  r.addFilter("default", defaultFilter);
  r.addFilter("d", defaultFilter);
  r.addFilter("length", lengthFilter);
  r.addFilter("count", lengthFilter);
  r.addFilter("first", firstFilter);
  r.addFilter("last", lastFilter);
  r.addFilter("list", listFilter);
  r.addFilter("items", itemsFilter);
  r.addFilter("reverse", reverseFilter);
  r.addFilter("attr", attrFilter);
  registerSelectFilters(r);
}

}  // namespace smachac::tmpl
