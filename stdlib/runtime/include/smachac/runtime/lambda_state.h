// LambdaState: a state whose execute() is a C++ callable, for generated code and tests.
//
//   std::make_unique<rt::LambdaState>(rt::StateSpec{.outcomes = {"done"}, .input_keys = {"x"}},
//       [](rt::UserData& ud) { return ud.get<double>("x") > 0 ? "done" : "done"; });
//
// The two-argument form also receives the state, to poll preemptRequested() or sleep with
// waitForPreempt().
#pragma once

#include <functional>
#include <string>

#include "smachac/runtime/state.h"

namespace smachac::runtime {

class LambdaState : public State {
 public:
  using Body = std::function<std::string(UserData&)>;
  using BodyWithState = std::function<std::string(State&, UserData&)>;

  /// Both constructors throw Error for an empty callable.
  LambdaState(StateSpec spec, Body body);
  LambdaState(StateSpec spec, BodyWithState body);

  std::string execute(UserData& userdata) override;

 private:
  BodyWithState body_;
};

}  // namespace smachac::runtime
