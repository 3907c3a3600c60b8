// MoveToJointPositionsState and FollowJointTrajActionState.
#include "smachac/robot/move_states.h"

#include "smachac/robot/formats.h"

namespace smachac::robot {
namespace {

rt::Keys inputs(const std::string& limb, const rt::Value& value, const char* key) {
  rt::Keys keys;
  if (limb.empty()) keys.push_back("limb");
  if (value.isNull()) keys.push_back(key);
  return keys;
}

}  // namespace

MoveToJointPositionsState::MoveToJointPositionsState(RobotContext& context,
                                                     MoveToJointPositionsArgs args)
    : RobotState(context, inputs(args.limb, args.positions, "positions")), args_(std::move(args)) {}

std::string MoveToJointPositionsState::run(rt::UserData& userdata) {
  const sim::Side side = limbOf(args_.limb, userdata);
  const auto goal = parseJointPositions(valueOf(args_.positions, "positions", userdata));
  return moveArm(side, goal, {args_.speed, args_.timeout});
}

FollowJointTrajActionState::FollowJointTrajActionState(RobotContext& context,
                                                       FollowJointTrajActionArgs args)
    : RobotState(context, inputs(args.limb, args.points, "points")), args_(std::move(args)) {}

std::string FollowJointTrajActionState::run(rt::UserData& userdata) {
  const sim::Side side = limbOf(args_.limb, userdata);
  for (const sim::JointPositions& point :
       parseJointPoints(valueOf(args_.points, "points", userdata))) {
    std::string outcome = moveArm(side, point, {args_.speed, args_.timeout});
    if (outcome != kSucceeded) return outcome;
  }
  return std::string(kSucceeded);
}

}  // namespace smachac::robot
