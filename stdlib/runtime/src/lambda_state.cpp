// LambdaState: execute() forwards to the callable given at construction.
#include "smachac/runtime/lambda_state.h"

#include "smachac/runtime/errors.h"

namespace smachac::runtime {
namespace {

template <typename Callable>
Callable required(Callable body) {
  if (!body) throw Error("a LambdaState needs a callable, got an empty one");
  return body;
}

}  // namespace

LambdaState::LambdaState(StateSpec spec, Body body)
    : State(std::move(spec)), body_([body = required(std::move(body))](State&, UserData& userdata) {
        return body(userdata);
      }) {}

LambdaState::LambdaState(StateSpec spec, BodyWithState body)
    : State(std::move(spec)), body_(required(std::move(body))) {}

std::string LambdaState::execute(UserData& userdata) { return body_(*this, userdata); }

}  // namespace smachac::runtime
