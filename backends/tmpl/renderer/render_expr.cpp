// Expression evaluation with Jinja2's semantics (attribute/item lookup order, chained
// comparisons, `and`/`or` returning operands, undefined values that fail when used).
#include <algorithm>

#include "backends/tmpl/error.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {
namespace {

[[noreturn]] void failUndefined(const Value& v) { fail(v.undefinedMessage()); }

Value undefinedItem(const Value& obj, const Value& key) {
  std::string owner(typeName(obj));
  if (key.isString()) {
    return Value::undefinedHint("`" + owner + "` object has no attribute `" + key.s() + "`");
  }
  return Value::undefinedHint("`" + owner + "` object has no element " + repr(key));
}

bool compareOne(CmpOp op, const Value& a, const Value& b) {
  switch (op) {
    case CmpOp::Eq:
      return equals(a, b);
    case CmpOp::Ne:
      return !equals(a, b);
    case CmpOp::Lt:
      return lessThan(a, b);
    case CmpOp::Le:
      return lessThan(a, b) || equals(a, b);
    case CmpOp::Gt:
      return lessThan(b, a);
    case CmpOp::Ge:
      return lessThan(b, a) || equals(a, b);
    case CmpOp::In:
      return contains(b, a);
    case CmpOp::NotIn:
      return !contains(b, a);
  }
  return false;
}

int64_t sliceIndex(const Value& v) {
  if (v.isInt() || v.isBool()) return v.integral();
  if (v.isUndefined()) failUndefined(v);
  fail("slice indices must be integers or None");
}

Value evalSlice(Exec& ex, Site& site, const Value& obj, const SliceExpr* s) {
  auto part = [&](const Expr* e) { return e ? eval(ex, site, e) : Value::none(); };
  Value start_v = part(s->start), stop_v = part(s->stop), step_v = part(s->step);
  if (obj.isUndefined()) failUndefined(obj);
  int64_t step = step_v.isNone() ? 1 : sliceIndex(step_v);
  if (step == 0) fail("slice step cannot be zero");
  std::vector<Value> items;
  bool is_string = obj.isString();
  if (is_string) {
    items = iterate(obj);
  } else if (obj.isListOrTuple()) {
    items = obj.list().items();
  } else {
    fail("`" + std::string(typeName(obj)) + "` object is not subscriptable");
  }
  auto n = static_cast<int64_t>(items.size());
  auto clamp = [&](const Value& v, int64_t fallback) {
    if (v.isNone()) return fallback;
    int64_t i = sliceIndex(v);
    if (i < 0) return std::max(i + n, step < 0 ? int64_t{-1} : int64_t{0});
    return std::min(i, step < 0 ? n - 1 : n);
  };
  int64_t start = clamp(start_v, step < 0 ? n - 1 : 0);
  int64_t stop = clamp(stop_v, step < 0 ? -1 : n);
  std::vector<Value> out;
  for (int64_t i = start; step > 0 ? i < stop : i > stop; i += step) out.push_back(items[i]);
  if (is_string) {
    std::string text;
    for (const Value& c : out) text += c.s();
    return Value::string(std::move(text), obj.isMarkup());
  }
  return obj.isList() ? Value::newList(std::move(out)) : Value::newTuple(std::move(out));
}

Value evalCompare(Exec& ex, Site& site, const CompareExpr* c) {
  Value left = eval(ex, site, c->first);
  for (const auto& [op, expr] : c->ops) {
    Value right = eval(ex, site, expr);
    if (!compareOne(op, left, right)) return Value::boolean(false);
    left = std::move(right);
  }
  return Value::boolean(true);
}

Value evalConcat(Exec& ex, Site& site, const ConcatExpr* c) {
  std::string out;
  for (const Expr* e : c->items) appendStr(out, eval(ex, site, e));
  checkSize(out.size(), "string");
  return Value::string(std::move(out));
}

Value evalDict(Exec& ex, Site& site, const DictExpr* d) {
  Value dict = Value::newDict();
  for (const auto& [k, v] : d->items) {
    Value key = eval(ex, site, k);
    dict.dict().set(key, eval(ex, site, v));
  }
  return dict;
}

Value evalSequence(Exec& ex, Site& site, const SeqExpr* s) {
  std::vector<Value> items;
  items.reserve(s->items.size());
  for (const Expr* e : s->items) items.push_back(eval(ex, site, e));
  return s->kind == ExprKind::List ? Value::newList(std::move(items))
                                   : Value::newTuple(std::move(items));
}

// `obj.name(...)`: builtin methods are called without materialising a bound method.
Value evalMethodCall(Exec& ex, Site& site, const CallExpr* call, const GetattrExpr* attr) {
  Value self = eval(ex, site, attr->object);
  if (self.isUndefined()) failUndefined(self);
  OwnedArgs args;
  if (!self.isObject() && hasMethod(self, *attr->attr)) {
    evalArgs(ex, site, call->args, args);
    Value out;
    callMethod(ex, self, *attr->attr, args.view(), out);
    return out;
  }
  Value fn = getAttribute(self, attr->attr);
  evalArgs(ex, site, call->args, args);
  return callValue(ex, fn, args.view());
}

Value evalCall(Exec& ex, Site& site, const CallExpr* call) {
  if (call->callee->kind == ExprKind::Getattr) {
    return evalMethodCall(ex, site, call, static_cast<const GetattrExpr*>(call->callee));
  }
  Value fn = eval(ex, site, call->callee);
  OwnedArgs args;
  evalArgs(ex, site, call->args, args);
  return callValue(ex, fn, args.view());
}

Value evalTest(Exec& ex, Site& site, const TestExpr* t) {
  Value input = eval(ex, site, t->input);
  OwnedArgs args;
  evalArgs(ex, site, t->args, args);
  return Value::boolean(applyTest(ex, *t->def, input, args.view()));
}

Value evalInner(Exec& ex, Site& site, const Expr* e) {
  switch (e->kind) {
    case ExprKind::Const:
      return static_cast<const ConstExpr*>(e)->value;
    case ExprKind::Name:
      return site.frame->slot(static_cast<const NameExpr*>(e)->ref).loaded();
    case ExprKind::List:
    case ExprKind::Tuple:
      return evalSequence(ex, site, static_cast<const SeqExpr*>(e));
    case ExprKind::Dict:
      return evalDict(ex, site, static_cast<const DictExpr*>(e));
    case ExprKind::Neg:
      return negate(eval(ex, site, static_cast<const UnaryExpr*>(e)->operand));
    case ExprKind::Pos:
      return unaryPlus(eval(ex, site, static_cast<const UnaryExpr*>(e)->operand));
    case ExprKind::Not:
      return Value::boolean(!truthy(eval(ex, site, static_cast<const UnaryExpr*>(e)->operand)));
    case ExprKind::Binary: {
      auto* b = static_cast<const BinaryExpr*>(e);
      Value left = eval(ex, site, b->left);
      Value right = eval(ex, site, b->right);
      return binary(b->op, left, right);
    }
    case ExprKind::And:
    case ExprKind::Or: {
      auto* b = static_cast<const BinaryExpr*>(e);
      Value left = eval(ex, site, b->left);
      if (truthy(left) == (e->kind == ExprKind::Or)) return left;
      return eval(ex, site, b->right);
    }
    case ExprKind::Concat:
      return evalConcat(ex, site, static_cast<const ConcatExpr*>(e));
    case ExprKind::Compare:
      return evalCompare(ex, site, static_cast<const CompareExpr*>(e));
    case ExprKind::CondExpr: {
      auto* c = static_cast<const CondExpr*>(e);
      if (truthy(eval(ex, site, c->test))) return eval(ex, site, c->then);
      if (c->otherwise) return eval(ex, site, c->otherwise);
      return Value::undefinedHint("the inline if-expression evaluated to false and has no else");
    }
    case ExprKind::Getattr: {
      auto* g = static_cast<const GetattrExpr*>(e);
      return getAttribute(eval(ex, site, g->object), g->attr);
    }
    case ExprKind::Getitem: {
      auto* g = static_cast<const GetitemExpr*>(e);
      Value obj = eval(ex, site, g->object);
      if (g->index->kind == ExprKind::Slice) {
        return evalSlice(ex, site, obj, static_cast<const SliceExpr*>(g->index));
      }
      return getItem(obj, eval(ex, site, g->index));
    }
    case ExprKind::Slice:
      fail("slice used outside a subscript");
    case ExprKind::Call:
      return evalCall(ex, site, static_cast<const CallExpr*>(e));
    case ExprKind::Filter:
      return applyFilterExpr(ex, site, static_cast<const FilterExpr*>(e), nullptr);
    case ExprKind::Test:
      return evalTest(ex, site, static_cast<const TestExpr*>(e));
    case ExprKind::NamespaceRef:
      fail("namespace references can only be assigned to");
  }
  return Value();
}

}  // namespace

Value evalExpr(Exec& ex, Site& site, const Expr* e) {
  try {
    return evalInner(ex, site, e);
  } catch (const Fault& fault) {
    throw ex.tmpl->error(e->pos, fault.message());
  }
}

void evalArgs(Exec& ex, Site& site, const ArgList& list, OwnedArgs& out) {
  out.positional.reserve(list.args.size());
  for (const Expr* e : list.args) out.positional.pushBack(eval(ex, site, e));
  if (list.dyn_args) {
    for (Value& v : iterate(eval(ex, site, list.dyn_args))) out.positional.pushBack(std::move(v));
  }
  for (const auto& [name, e] : list.kwargs) out.keyword.emplaceBack(name, eval(ex, site, e));
  if (list.dyn_kwargs) {
    Value d = eval(ex, site, list.dyn_kwargs);
    if (!d.isDict()) fail("argument after `**` must be a mapping");
    for (const auto& [k, v] : d.dict().entries()) {
      if (!k.isString()) fail("keywords must be strings");
      out.keyword.emplaceBack(intern(k.s()), v);
    }
  }
}

Value getAttribute(const Value& obj, const std::string* name) {
  switch (obj.kind()) {
    case Kind::Undefined:
      failUndefined(obj);
    case Kind::Dict:
      if (hasMethod(obj, *name)) return Value::object(new MethodObject(obj, *name));
      if (const Value* v = obj.dict().findString(*name)) return *v;
      break;
    case Kind::String:
    case Kind::List:
    case Kind::Tuple:
      if (hasMethod(obj, *name)) return Value::object(new MethodObject(obj, *name));
      break;
    case Kind::Int:
    case Kind::Bool:
    case Kind::Float:
      if (*name == "real") return obj.isFloat() ? obj : Value::integer(obj.integral());
      if (*name == "imag") return obj.isFloat() ? Value::real(0.0) : Value::integer(0);
      break;
    case Kind::Object: {
      Value out;
      if (obj.object()->getAttr(*name, out)) return out;
      break;
    }
    default:
      break;
  }
  return Value::undefinedAttribute(obj, name);
}

Value getItem(const Value& obj, const Value& key) {
  switch (obj.kind()) {
    case Kind::Undefined:
      failUndefined(obj);
    case Kind::Dict:
      try {
        if (const Value* v = obj.dict().find(key)) return *v;
      } catch (const Fault&) {
        // unhashable key: Jinja falls back to an undefined value
      }
      break;
    case Kind::List:
    case Kind::Tuple:
    case Kind::String: {
      if (!key.isInt() && !key.isBool()) break;
      int64_t n = obj.isString() ? static_cast<int64_t>(unicode::length(obj.s()))
                                 : static_cast<int64_t>(obj.list().items().size());
      int64_t i = key.integral();
      if (i < 0) i += n;
      if (i < 0 || i >= n) return undefinedItem(obj, key);
      if (!obj.isString()) return obj.list().items()[static_cast<size_t>(i)];
      return iterate(obj)[static_cast<size_t>(i)];
    }
    default:
      break;
  }
  if (key.isString()) {
    if (!obj.isObject() && obj.kind() >= Kind::String && hasMethod(obj, key.s())) {
      return Value::object(new MethodObject(obj, key.s()));
    }
    Value out;
    if (obj.isObject() && obj.object()->getAttr(key.s(), out)) return out;
  }
  return undefinedItem(obj, key);
}

Value callValue(Exec& ex, const Value& fn, const CallArgs& args) {
  if (fn.isUndefined()) failUndefined(fn);
  if (fn.isObject() && fn.object()->isCallable()) return fn.object()->call(ex, args);
  fail("`" + std::string(typeName(fn)) + "` object is not callable");
}

namespace {

bool isConstArgs(const ArgList& list, size_t max_positional) {
  if (list.args.size() > max_positional || !list.kwargs.empty()) return false;
  if (list.dyn_args || list.dyn_kwargs) return false;
  return std::all_of(list.args.begin(), list.args.end(),
                     [](const Expr* e) { return e->kind == ExprKind::Const; });
}

// The `map('f')` under `join` in `seq | map('f') | join(sep)` (SMACHA's render_list), when
// both take only constants (so evaluating them has no effect whose order could show).
const FilterExpr* mapUnderJoin(const FilterExpr* join) {
  static const FilterDef* const kJoin = builtinTable().filter("join");
  static const FilterDef* const kMap = builtinTable().filter("map");
  if (join->def != kJoin || !join->input || join->input->kind != ExprKind::Filter) return nullptr;
  auto* map = static_cast<const FilterExpr*>(join->input);
  if (map->def != kMap || !map->input || map->args.args.size() != 1) return nullptr;
  if (!isConstArgs(map->args, 1) || !isConstArgs(join->args, 1)) return nullptr;
  const Value& name = static_cast<const ConstExpr*>(map->args.args[0])->value;
  return name.isString() ? map : nullptr;
}

// `join(sep)` of the mapped items, as joinFilter joins a list (join's errors at `join`).
Value joinMapped(Exec& ex, const FilterExpr* join, const SmallVector<Value, 8>& mapped) {
  try {
    std::string converted;  // a separator that is not a string, as str() prints it
    const Value* sep = join->args.args.empty()
                           ? nullptr
                           : &static_cast<const ConstExpr*>(join->args.args[0])->value;
    if (sep && !sep->isString()) converted = str(*sep);
    std::string_view separator = sep && sep->isString() ? std::string_view(sep->s()) : converted;
    std::string out;
    for (size_t i = 0; i < mapped.size(); ++i) {
      if (i > 0) out += separator;
      appendStr(out, mapped[i]);
      checkSize(out.size(), "string");
    }
    return Value::string(std::move(out));
  } catch (const Fault& fault) {
    throw ex.tmpl->error(join->pos, fault.message());
  }
}

// `seq | map('f') | join(sep)` without the mapped list's object and join's argument binding:
// the same items, separator, results and errors (each located at its filter) as the chain.
Value mapJoin(Exec& ex, Site& site, const FilterExpr* join, const FilterExpr* map) {
  Value input = eval(ex, site, map->input);
  SmallVector<Value, 8> mapped;
  try {
    const FilterDef* def = map->mapped;
    if (!def) {
      const std::string& name = static_cast<const ConstExpr*>(map->args.args[0])->value.s();
      def = ex.registry.filter(name);
      if (!def) fail("no filter named `" + name + "`");
      map->mapped = def;
    }
    if (truthy(input)) {
      for (const Value& item : iterate(input)) mapped.pushBack(applyFilter(ex, *def, item, {}));
    }
    chargeWork(mapped.size() * sizeof(Value));  // the steps of the list `map` would make
  } catch (const Fault& fault) {
    throw ex.tmpl->error(map->pos, fault.message());
  }
  return joinMapped(ex, join, mapped);
}

}  // namespace

Value applyFilterExpr(Exec& ex, Site& site, const FilterExpr* filter, const Value* block_input) {
  if (const FilterExpr* map = mapUnderJoin(filter)) return mapJoin(ex, site, filter, map);
  Value input;
  if (filter->input && filter->input->kind == ExprKind::Filter && block_input) {
    input = applyFilterExpr(ex, site, static_cast<const FilterExpr*>(filter->input), block_input);
  } else if (filter->input) {
    input = eval(ex, site, filter->input);
  } else if (block_input) {
    input = *block_input;
  }
  OwnedArgs args;
  evalArgs(ex, site, filter->args, args);
  try {
    return applyFilter(ex, *filter->def, input, args.view());
  } catch (const Fault& fault) {
    throw ex.tmpl->error(filter->pos, fault.message());
  }
}

}  // namespace smachac::tmpl
