// ReadEndpointPoseState: the TCP pose into userdata.
#include "smachac/robot/read_endpoint_pose_state.h"

#include "smachac/robot/formats.h"
#include "smachac/sim/limb.h"

namespace smachac::robot {

ReadEndpointPoseState::ReadEndpointPoseState(RobotContext& context, ReadEndpointPoseArgs args)
    : RobotState(context, args.limb.empty() ? rt::Keys{"limb"} : rt::Keys{}, {"pose"}),
      args_(std::move(args)) {}

std::string ReadEndpointPoseState::run(rt::UserData& userdata) {
  const sim::Side side = limbOf(args_.limb, userdata);
  userdata.set("pose", poseValue(world().limb(side).endpointPose(sim::Frame::Base)));
  return std::string(kSucceeded);
}

}  // namespace smachac::robot
