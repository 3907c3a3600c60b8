// Type inference from literals, joins and printing.
#include "ir/type.h"

namespace smachac::ir {

Type Type::listOf(Type element) {
  Type t(Kind::ListOf);
  t.element_ = std::make_shared<const Type>(std::move(element));
  return t;
}

Type Type::mapOf(Type element) {
  Type t(Kind::MapOf);
  t.element_ = std::make_shared<const Type>(std::move(element));
  return t;
}

Type Type::element() const { return element_ ? *element_ : any(); }

Type Type::ofValue(const Value& value) {
  switch (value.kind()) {
    case ValueKind::Null:
      return of(Kind::Null);
    case ValueKind::Bool:
      return of(Kind::Bool);
    case ValueKind::Int:
      return of(Kind::Int);
    case ValueKind::Float:
      return of(Kind::Float);
    case ValueKind::String:
      return of(Kind::String);
    case ValueKind::Expression:
      return of(Kind::Expression);
    case ValueKind::List: {
      const List& items = value.asList();
      if (items.empty()) return listOf(any());
      Type element = ofValue(items.front());
      for (size_t i = 1; i < items.size(); ++i) element = join(element, ofValue(items[i]));
      return listOf(element);
    }
    case ValueKind::Map: {
      const Map& entries = value.asMap();
      if (entries.empty()) return mapOf(any());
      Type element = ofValue(entries.front().value);
      for (size_t i = 1; i < entries.size(); ++i) {
        element = join(element, ofValue(entries[i].value));
      }
      return mapOf(element);
    }
  }
  return any();
}

Type Type::join(const Type& a, const Type& b) {
  if (a == b) return a;
  auto numeric = [](Kind k) { return k == Kind::Int || k == Kind::Float; };
  if (numeric(a.kind_) && numeric(b.kind_)) return of(Kind::Float);
  if (a.kind_ == b.kind_ && (a.kind_ == Kind::ListOf || a.kind_ == Kind::MapOf)) {
    Type element = join(a.element(), b.element());
    return a.kind_ == Kind::ListOf ? listOf(element) : mapOf(element);
  }
  return any();
}

bool operator==(const Type& a, const Type& b) {
  if (a.kind_ != b.kind_) return false;
  if (a.kind_ != Type::Kind::ListOf && a.kind_ != Type::Kind::MapOf) return true;
  return a.element() == b.element();
}

std::string Type::str() const {
  switch (kind_) {
    case Kind::Any:
      return "any";
    case Kind::Null:
      return "null";
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::String:
      return "string";
    case Kind::Expression:
      return "expr";
    case Kind::ListOf:
      return "list<" + element().str() + ">";
    case Kind::MapOf:
      return "map<string, " + element().str() + ">";
  }
  return "any";
}

}  // namespace smachac::ir
