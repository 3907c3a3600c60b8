// RobotState: inputs from variables or userdata, preemptible arm moves, aborting.
#include "smachac/robot/robot_state.h"

#include <cstdio>

#include "smachac/robot/formats.h"
#include "smachac/sim/limb.h"

namespace smachac::robot {

RobotState::RobotState(RobotContext& context, rt::Keys inputs, rt::Keys outputs)
    : rt::State(rt::StateSpec{
          .outcomes = {std::string(kSucceeded), std::string(kAborted), std::string(rt::kPreempted)},
          .input_keys = std::move(inputs),
          .output_keys = std::move(outputs)}),
      context_(context) {}

std::string RobotState::execute(rt::UserData& userdata) {
  if (preemptRequested()) return preempted();
  context_.beginExecution();
  struct End {
    RobotContext& context;
    ~End() { context.endExecution(); }
  } end{context_};
  return run(userdata);
}

sim::Side RobotState::limbOf(const std::string& variable, rt::UserData& userdata) const {
  return parseLimb(variable.empty() ? userdata.get<std::string>("limb") : variable);
}

rt::Value RobotState::valueOf(const rt::Value& variable, std::string_view key,
                              rt::UserData& userdata) {
  return variable.isNull() ? userdata.at(key) : variable;
}

std::optional<rt::Value> RobotState::optionalValueOf(const rt::Value& variable,
                                                     std::string_view key, rt::UserData& userdata) {
  if (!variable.isNull()) return variable;
  return userdata.find(key);
}

std::string RobotState::moveArm(sim::Side side, const sim::JointPositions& goal,
                                const MoveSettings& settings) {
  sim::MoveOptions options = context_.options().move;
  options.speed = settings.speed.value_or(options.speed);
  options.timeout = settings.timeout.value_or(options.timeout);
  sim::Limb& limb = world().limb(side);
  if (!limb.startMove(goal, options)) return abort("joint positions outside the joint limits");
  const bool reached =
      context_.stepUntil([&] { return preemptRequested() || limb.moveDone(); }, options.timeout);
  if (preemptRequested()) {
    limb.holdCurrent();
    return preempted();
  }
  if (!reached) {
    char error[64];
    std::snprintf(error, sizeof error, "%.4f rad", limb.moveError());
    return abort(std::string("move timed out ") + error + " from the goal");
  }
  return std::string(kSucceeded);
}

std::string RobotState::abort(std::string_view why) {
  context_.log(path(), why);
  context_.snapshot(path());
  return std::string(kAborted);
}

std::string RobotState::preempted() {
  servicePreempt();
  context_.log(path(), "preempted");
  return std::string(rt::kPreempted);
}

}  // namespace smachac::robot
