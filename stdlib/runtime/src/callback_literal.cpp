// CallbacksLiteral's conversion to Callbacks, out of line: generated code only names it.
#include "smachac/runtime/callback_literal.h"

#include <string>

#include "smachac/runtime/core_states.h"

namespace smachac::runtime {

Callback CallbackLiteral::callback() const {
  if (invoke_ != nullptr) return Callback(invoke_);
  return make_(*this);
}

CallbacksLiteral::operator std::vector<KeyedCallback>() const {
  std::vector<KeyedCallback> callbacks;
  callbacks.reserve(entries_.size());
  for (const CallbackLiteral& entry : entries_) {
    callbacks.push_back({.key = std::string(entry.key()), .callback = entry.callback()});
  }
  return callbacks;
}

}  // namespace smachac::runtime
