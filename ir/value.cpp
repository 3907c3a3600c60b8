// Value construction, lookup, comparison and description.
#include "ir/value.h"

#include <fmt/core.h>

#include "ir/expr.h"

namespace smachac::ir {

// A big script's document tree is mostly values: keep them small (ExpressionPtr).
static_assert(sizeof(Value) <= 64);
static_assert(sizeof(MapEntry) <= 112);

std::string_view valueKindName(ValueKind kind) {
  switch (kind) {
    case ValueKind::Null:
      return "null";
    case ValueKind::Bool:
      return "bool";
    case ValueKind::Int:
      return "int";
    case ValueKind::Float:
      return "float";
    case ValueKind::String:
      return "string";
    case ValueKind::Expression:
      return "expression";
    case ValueKind::List:
      return "list";
    case ValueKind::Map:
      return "map";
  }
  return "null";
}

Value Value::null(SourceLoc loc) { return Value{{}, loc}; }
Value Value::boolean(bool b, SourceLoc loc) { return Value{b, loc}; }
Value Value::integer(int64_t i, SourceLoc loc) { return Value{i, loc}; }
Value Value::real(double d, SourceLoc loc) { return Value{d, loc}; }
Value Value::string(std::string s, SourceLoc loc) { return Value{std::move(s), loc}; }
Value Value::expression(std::string code, SourceLoc loc) {
  return Value{std::make_shared<const Expression>(Expression{std::move(code), nullptr}), loc};
}
Value Value::portable(std::shared_ptr<const PortableExpr> expr, SourceLoc loc) {
  std::string text = expr->text;
  return Value{std::make_shared<const Expression>(Expression{std::move(text), std::move(expr)}),
               loc};
}

const PortableExpr* Value::asPortable() const {
  const ExpressionPtr* e = std::get_if<ExpressionPtr>(&data);
  return e ? (*e)->portable.get() : nullptr;
}

Value Value::list(List items, SourceLoc loc) { return Value{std::move(items), loc}; }
Value Value::map(Map entries, SourceLoc loc) { return Value{std::move(entries), loc}; }

const Value* Value::find(std::string_view key) const {
  if (!isMap()) return nullptr;
  for (const MapEntry& entry : asMap()) {
    if (entry.key == key) return &entry.value;
  }
  return nullptr;
}

Value* Value::find(std::string_view key) {
  return const_cast<Value*>(static_cast<const Value*>(this)->find(key));
}

bool sameValue(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case ValueKind::List: {
      const List& x = a.asList();
      const List& y = b.asList();
      if (x.size() != y.size()) return false;
      for (size_t i = 0; i < x.size(); ++i) {
        if (!sameValue(x[i], y[i])) return false;
      }
      return true;
    }
    case ValueKind::Map: {
      const Map& x = a.asMap();
      const Map& y = b.asMap();
      if (x.size() != y.size()) return false;
      for (size_t i = 0; i < x.size(); ++i) {
        if (x[i].key != y[i].key || !sameValue(x[i].value, y[i].value)) return false;
      }
      return true;
    }
    case ValueKind::Null:
      return true;
    case ValueKind::Bool:
      return a.asBool() == b.asBool();
    case ValueKind::Int:
      return a.asInt() == b.asInt();
    case ValueKind::Float:
      return a.asFloat() == b.asFloat();
    case ValueKind::String:
      return a.asString() == b.asString() && a.forced_string == b.forced_string;
    case ValueKind::Expression:
      return a.asExpression() == b.asExpression();
  }
  return false;
}

std::string describeValue(const Value& value) {
  switch (value.kind()) {
    case ValueKind::Null:
      return "null";
    case ValueKind::Bool:
      return value.asBool() ? "the boolean `true`" : "the boolean `false`";
    case ValueKind::Int:
      return fmt::format("the integer `{}`", value.asInt());
    case ValueKind::Float:
      return "a float";
    case ValueKind::String:
      return value.asString().size() <= 40 ? fmt::format("the string `{}`", value.asString())
                                           : "a string";
    case ValueKind::Expression:
      return "an expression";
    case ValueKind::List:
      return "a list";
    case ValueKind::Map:
      return "a mapping";
  }
  return "a value";
}

}  // namespace smachac::ir
