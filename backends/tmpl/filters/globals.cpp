// Global functions available to every template: range, dict, namespace, joiner.
#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {
namespace {

using Args = const CallArgs&;

class RangeObject final : public Object {
 public:
  RangeObject(int64_t start, int64_t stop, int64_t step)
      : start_(start), stop_(stop), step_(step) {}
  std::string_view typeName() const override { return "range"; }
  void repr(std::string& out) const override {
    out += "range(" + std::to_string(start_) + ", " + std::to_string(stop_);
    if (step_ != 1) out += ", " + std::to_string(step_);
    out += ")";
  }
  bool iterate(std::vector<Value>& out) const override {
    for (int64_t i = start_; step_ > 0 ? i < stop_ : i > stop_; i += step_) {
      out.push_back(Value::integer(i));
      checkSize(out.size(), "list");
    }
    return true;
  }

 private:
  int64_t start_, stop_, step_;
};

int64_t intArg(const Value& v) {
  if (v.isInt() || v.isBool()) return v.integral();
  if (v.isUndefined()) fail(v.undefinedMessage());
  fail("`" + std::string(typeName(v)) + "` object cannot be interpreted as an integer");
}

Value rangeFn(Exec&, Args args) {
  if (!args.keyword.empty()) fail("range() takes no keyword arguments");
  size_t n = args.positional.size();
  if (n < 1 || n > 3) fail("range expected 1 to 3 arguments, got " + std::to_string(n));
  int64_t start = n == 1 ? 0 : intArg(args.positional[0]);
  int64_t stop = intArg(args.positional[n == 1 ? 0 : 1]);
  int64_t step = n == 3 ? intArg(args.positional[2]) : 1;
  if (step == 0) fail("range() arg 3 must not be zero");
  return Value::object(new RangeObject(start, stop, step));
}

Value dictFn(Exec& ex, Args args) {
  Value out = Value::newDict();
  if (args.positional.size() > 1) fail("dict expected at most 1 argument");
  if (!args.positional.empty()) {
    OwnedArgs update;
    update.positional.pushBack(args.positional[0]);
    Value ignored;
    callMethod(ex, out, "update", update.view(), ignored);
  }
  for (const auto& [k, v] : args.keyword) out.dict().setString(*k, v);
  return out;
}

class NamespaceObject final : public Object {
 public:
  NamespaceObject() : attrs_(Value::newDict()) {}
  std::string_view typeName() const override { return "Namespace"; }
  void repr(std::string& out) const override {
    out += "<Namespace ";
    appendRepr(out, attrs_);
    out += ">";
  }
  bool getAttr(std::string_view name, Value& out) const override {
    const Value* v = attrs_.dict().findString(name);
    if (!v) return false;
    out = *v;
    return true;
  }
  void set(const std::string& name, const Value& v) { attrs_.dict().setString(name, v); }
  const Value& attrs() const { return attrs_; }

 private:
  Value attrs_;
};

Value namespaceFn(Exec& ex, Args args) {
  Value ns = Value::object(new NamespaceObject());
  auto* object = static_cast<NamespaceObject*>(const_cast<Object*>(ns.object()));
  Value init = dictFn(ex, args);
  for (const auto& [k, v] : init.dict().entries()) object->set(str(k), v);
  return ns;
}

class JoinerObject final : public Object {
 public:
  explicit JoinerObject(std::string sep) : sep_(std::move(sep)) {}
  std::string_view typeName() const override { return "Joiner"; }
  bool isCallable() const override { return true; }
  Value call(Exec&, Args) const override {
    if (!used_) {
      used_ = true;
      return Value::string("");
    }
    return Value::string(sep_);
  }

 private:
  std::string sep_;
  mutable bool used_ = false;
};

Value joinerFn(Exec&, Args args) {
  ArgBinder b(args, "joiner", {"sep"});
  return Value::object(new JoinerObject(b.has(0) ? str(*b.get(0)) : ", "));
}

}  // namespace

bool setNamespaceAttribute(const Value& ns, const std::string& name, const Value& value) {
  if (!ns.isObject()) return false;
  auto* object = dynamic_cast<const NamespaceObject*>(ns.object());
  if (!object) return false;
  const_cast<NamespaceObject*>(object)->set(name, value);
  return true;
}

void registerBuiltinGlobals(Registry& r) {
  r.addGlobal("range", Value::object(new FunctionObject("range", rangeFn)));
  r.addGlobal("dict", Value::object(new FunctionObject("dict", dictFn)));
  r.addGlobal("namespace", Value::object(new FunctionObject("namespace", namespaceFn)));
  r.addGlobal("joiner", Value::object(new FunctionObject("joiner", joinerFn)));
}

}  // namespace smachac::tmpl
