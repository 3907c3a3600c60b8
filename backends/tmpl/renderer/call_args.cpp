// Call arguments and their binding to Python-like parameter lists (see call_args.h).
#include "backends/tmpl/renderer/call_args.h"

#include <algorithm>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {
namespace {

[[noreturn]] void failTooManyParams(std::string_view function) {
  fail("internal: too many parameters for `" + std::string(function) + "`");
}

[[noreturn]] void failTooManyArgs(std::string_view function, size_t most, size_t given) {
  fail("`" + std::string(function) + "` takes at most " + std::to_string(most) + " argument(s) (" +
       std::to_string(given) + " given)");
}

}  // namespace

const Value* CallArgs::findKeyword(std::string_view name) const {
  for (const auto& [n, v] : keyword) {
    if (*n == name) return &v;
  }
  return nullptr;
}

ArgBinder::ArgBinder(const CallArgs& args, std::string_view function,
                     std::initializer_list<std::string_view> params)
    : function_(function), count_(params.size()) {
  if (count_ > kMaxParams) failTooManyParams(function);
  for (size_t i = 0; i < count_; ++i)
    params_[i] = {params.begin()[i].data(), params.begin()[i].size()};
  size_t n = count_;
  if (args.positional.size() > n) failTooManyArgs(function_, n, args.positional.size());
  for (size_t i = 0; i < args.positional.size(); ++i) bound_[i] = &args.positional[i];
  for (const auto& [name, value] : args.keyword) {
    size_t i = 0;
    while (i < n && params_[i].view() != *name) ++i;
    if (i == n || bound_[i]) failKeyword(*name, i < n);
    bound_[i] = &value;
  }
}

void ArgBinder::failKeyword(const std::string& name, bool duplicate) const {
  if (duplicate) {
    fail("`" + std::string(function_) + "` got multiple values for argument `" + name + "`");
  }
  fail("`" + std::string(function_) + "` got an unexpected keyword argument `" + name + "`");
}

const Value& ArgBinder::require(size_t index) const {
  if (!bound_[index]) {
    fail("`" + std::string(function_) + "` is missing the required argument `" +
         std::string(params_[index].view()) + "`");
  }
  return *bound_[index];
}

void ArgBinder::failNotInt(size_t index) const {
  const Value* v = bound_[index];
  if (v->isUndefined()) fail(v->undefinedMessage());
  fail("`" + std::string(function_) + "` expects an integer for `" +
       std::string(params_[index].view()) + "`, not `" + std::string(typeName(*v)) + "`");
}

bool ArgBinder::truthyOf(const Value& v) { return truthy(v); }

}  // namespace smachac::tmpl
