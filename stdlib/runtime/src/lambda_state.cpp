// LambdaState: execute() forwards to the callable given at construction.
#include "smachac/runtime/lambda_state.h"

namespace smachac::runtime {

LambdaState::LambdaState(StateSpec spec, Body body)
    : State(std::move(spec)),
      body_([body = std::move(body)](State&, UserData& userdata) { return body(userdata); }) {}

LambdaState::LambdaState(StateSpec spec, BodyWithState body)
    : State(std::move(spec)), body_(std::move(body)) {}

std::string LambdaState::execute(UserData& userdata) { return body_(*this, userdata); }

}  // namespace smachac::runtime
