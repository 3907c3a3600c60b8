// Call arguments and their binding to Python-like parameter lists (see call_args.h).
#include "backends/tmpl/renderer/call_args.h"

#include <algorithm>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {

const Value* CallArgs::findKeyword(std::string_view name) const {
  for (const auto& [n, v] : keyword) {
    if (*n == name) return &v;
  }
  return nullptr;
}

ArgBinder::ArgBinder(const CallArgs& args, std::string_view function,
                     std::initializer_list<std::string_view> params)
    : function_(function), count_(params.size()) {
  if (count_ > kMaxParams)
    fail("internal: too many parameters for `" + std::string(function) + "`");
  std::copy(params.begin(), params.end(), params_);
  size_t n = count_;
  if (args.positional.size() > n) {
    fail("`" + std::string(function_) + "` takes at most " + std::to_string(n) + " argument(s) (" +
         std::to_string(args.positional.size()) + " given)");
  }
  for (size_t i = 0; i < args.positional.size(); ++i) bound_[i] = &args.positional[i];
  for (const auto& [name, value] : args.keyword) {
    size_t i = 0;
    while (i < n && params_[i] != *name) ++i;
    if (i == n) {
      fail("`" + std::string(function_) + "` got an unexpected keyword argument `" + *name + "`");
    }
    if (bound_[i]) {
      fail("`" + std::string(function_) + "` got multiple values for argument `" + *name + "`");
    }
    bound_[i] = &value;
  }
}

const Value& ArgBinder::require(size_t index) const {
  if (!bound_[index]) {
    fail("`" + std::string(function_) + "` is missing the required argument `" +
         std::string(params_[index]) + "`");
  }
  return *bound_[index];
}

int64_t ArgBinder::getInt(size_t index, int64_t fallback) const {
  const Value* v = bound_[index];
  if (!v) return fallback;
  if (v->isInt() || v->isBool()) return v->integral();
  if (v->isUndefined()) fail(v->undefinedMessage());
  fail("`" + std::string(function_) + "` expects an integer for `" + std::string(params_[index]) +
       "`, not `" + std::string(typeName(*v)) + "`");
}

bool ArgBinder::getBool(size_t index, bool fallback) const {
  const Value* v = bound_[index];
  return v ? truthy(*v) : fallback;
}

}  // namespace smachac::tmpl
