// Filters that transform sequences item by item: map, select, reject, selectattr, rejectattr,
// batch, slice, groupby.
#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/attr_path.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/string_ops.h"
#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

CallArgs tailArgs(Args args, size_t skip) {
  return CallArgs{args.positional.subspan(std::min(skip, args.positional.size())), args.keyword};
}

Value mapFilter(Exec& ex, const Value& in, Args args) {
  if (!truthy(in)) return Value::newList();
  std::vector<Value> out;
  if (args.positional.empty() && args.findKeyword("attribute")) {
    ArgBinder b(args, "map", {"attribute", "default"});
    AttrPath path(b.require(0));
    Value fallback = b.get(1, Value::none());
    for (const Value& item : iterate(in)) {
      Value v = path.get(item);
      out.push_back(v.isUndefined() && !fallback.isNone() ? fallback : v);
    }
    return Value::newList(std::move(out));
  }
  if (args.positional.empty()) fail("`map` requires a filter argument");
  const std::string& name = stringArg(args.positional[0], "map");
  const FilterDef* def = ex.registry.filter(name);
  if (!def) fail("no filter named `" + name + "`");
  CallArgs rest = tailArgs(args, 1);
  for (const Value& item : iterate(in)) out.push_back(applyFilter(ex, *def, item, rest));
  return Value::newList(std::move(out));
}

Value selectOrReject(Exec& ex, const Value& in, Args args, bool select, bool by_attribute) {
  if (!truthy(in)) return Value::newList();
  AttrPath path;
  size_t offset = 0;
  if (by_attribute) {
    if (args.positional.empty()) fail("missing parameter for attribute name");
    path = AttrPath(args.positional[0]);
    offset = 1;
  }
  const TestDef* test = nullptr;
  if (args.positional.size() > offset) {
    const std::string& name = stringArg(args.positional[offset], "select");
    test = ex.registry.test(name);
    if (!test) fail("no test named `" + name + "`");
  }
  CallArgs rest = tailArgs(args, offset + 1);
  std::vector<Value> out;
  for (const Value& item : iterate(in)) {
    Value v = path.get(item);
    bool ok = test ? applyTest(ex, *test, v, rest) : truthy(v);
    if (ok == select) out.push_back(item);
  }
  return Value::newList(std::move(out));
}

Value selectFilter(Exec& ex, const Value& in, Args args) {
  return selectOrReject(ex, in, args, true, false);
}
Value rejectFilter(Exec& ex, const Value& in, Args args) {
  return selectOrReject(ex, in, args, false, false);
}
Value selectattrFilter(Exec& ex, const Value& in, Args args) {
  return selectOrReject(ex, in, args, true, true);
}
Value rejectattrFilter(Exec& ex, const Value& in, Args args) {
  return selectOrReject(ex, in, args, false, true);
}

Value batchFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "batch", {"linecount", "fill_with"});
  int64_t count = b.getInt(0, 0);
  b.require(0);
  std::vector<Value> out;
  std::vector<Value> current;
  for (const Value& item : iterate(in)) {
    if (static_cast<int64_t>(current.size()) == count) {
      out.push_back(Value::newList(std::move(current)));
      current.clear();
    }
    current.push_back(item);
  }
  if (!current.empty()) {
    if (b.has(1) && !b.get(1)->isNone()) {
      while (static_cast<int64_t>(current.size()) < count) current.push_back(*b.get(1));
    }
    out.push_back(Value::newList(std::move(current)));
  }
  return Value::newList(std::move(out));
}

Value sliceFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "slice", {"slices", "fill_with"});
  int64_t slices = b.getInt(0, 0);
  b.require(0);
  if (slices == 0) fail("integer division or modulo by zero");
  std::vector<Value> seq = iterate(in);
  auto n = static_cast<int64_t>(seq.size());
  int64_t per_slice = n / slices - ((n % slices != 0 && ((n < 0) != (slices < 0))) ? 1 : 0);
  int64_t with_extra = ((n % slices) + slices) % slices;
  int64_t offset = 0;
  std::vector<Value> out;
  for (int64_t i = 0; i < slices; ++i) {
    int64_t start = offset + i * per_slice;
    if (i < with_extra) ++offset;
    int64_t end = offset + (i + 1) * per_slice;
    std::vector<Value> part;
    for (int64_t k = std::max<int64_t>(start, 0); k < std::min(end, n); ++k)
      part.push_back(seq[static_cast<size_t>(k)]);
    if (b.has(1) && !b.get(1)->isNone() && i >= with_extra) part.push_back(*b.get(1));
    out.push_back(Value::newList(std::move(part)));
  }
  return Value::newList(std::move(out));
}

Value groupbyFilter(Exec&, const Value& in, Args args) {
  ArgBinder b(args, "groupby", {"attribute", "default", "case_sensitive"});
  AttrPath path(b.require(0));
  Value fallback = b.get(1, Value::none());
  bool case_sensitive = b.getBool(2, false);
  auto real_key = [&](const Value& item) {
    Value v = path.get(item);
    return v.isUndefined() && !fallback.isNone() ? fallback : v;
  };
  std::vector<Value> items = iterate(in);
  std::vector<Value> keys;
  for (const Value& item : items)
    keys.push_back(case_sensitive ? real_key(item) : ignoreCase(real_key(item)));
  std::vector<Value> indices;
  for (size_t i = 0; i < items.size(); ++i)
    indices.push_back(Value::integer(static_cast<int64_t>(i)));
  std::vector<Value> sorted = sortValues(indices, false, &keys);
  std::vector<Value> groups;
  for (size_t i = 0; i < sorted.size();) {
    auto first = static_cast<size_t>(sorted[i].i());
    std::vector<Value> members;
    size_t j = i;
    while (j < sorted.size() && equals(keys[static_cast<size_t>(sorted[j].i())], keys[first])) {
      members.push_back(items[static_cast<size_t>(sorted[j].i())]);
      ++j;
    }
    Value grouper = case_sensitive ? keys[first] : real_key(items[first]);
    groups.push_back(Value::newTuple({grouper, Value::newList(std::move(members))}));
    i = j;
  }
  return Value::newList(std::move(groups));
}

}  // namespace

void registerSelectFilters(BuiltinTable& r) {
  r.addFilter("map", mapFilter);
  r.addFilter("select", selectFilter);
  r.addFilter("reject", rejectFilter);
  r.addFilter("selectattr", selectattrFilter);
  r.addFilter("rejectattr", rejectattrFilter);
  r.addFilter("batch", batchFilter);
  r.addFilter("slice", sliceFilter);
  r.addFilter("groupby", groupbyFilter);
}

}  // namespace smachac::tmpl
