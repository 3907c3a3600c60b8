// PoseToJointTrajServiceState: pose (+ offset) -> IK -> joint positions.
#include "smachac/robot/pose_to_joint_traj_service_state.h"

#include <cstdio>

#include "smachac/robot/formats.h"
#include "smachac/sim/ik.h"

namespace smachac::robot {
namespace {

rt::Keys inputs(const PoseToJointTrajServiceArgs& args) {
  rt::Keys keys;
  if (args.limb.empty()) keys.push_back("limb");
  if (args.poses.isNull()) keys.push_back("poses");
  if (args.offsets.isNull()) keys.push_back("offsets");
  return keys;
}

std::string describe(const sim::Pose& pose, const sim::IkResult& result) {
  char text[160];
  std::snprintf(text, sizeof text,
                "no IK solution for (%.3f, %.3f, %.3f): position error %.3f m after %d iterations",
                pose.position.x, pose.position.y, pose.position.z, result.position_error,
                result.iterations);
  return text;
}

}  // namespace

PoseToJointTrajServiceState::PoseToJointTrajServiceState(RobotContext& context,
                                                         PoseToJointTrajServiceArgs args)
    : RobotState(context, inputs(args), {"joints"}), args_(std::move(args)) {}

PoseToJointTrajServiceState::~PoseToJointTrajServiceState() = default;

std::string PoseToJointTrajServiceState::run(rt::UserData& userdata) {
  const sim::Side side = limbOf(args_.limb, userdata);
  sim::Pose target = parsePose(valueOf(args_.poses, "poses", userdata));
  if (auto offset = optionalValueOf(args_.offsets, "offsets", userdata)) {
    target = applyOffset(target, parseOffset(*offset));
  }
  if (!ik_) ik_ = std::make_unique<sim::Ik>(world());
  const sim::IkResult result = ik_->solve(side, target, sim::Frame::Base);
  if (!result.ok()) return abort(describe(target, result));
  userdata.set("joints", jointsValue(result.joints));
  return std::string(kSucceeded);
}

}  // namespace smachac::robot
