// ReadEndpointPoseState: reads a limb's endpoint (TCP) pose in Baxter's base frame.
//
//   variable   input key   meaning
//   limb       limb        `left` or `right`
//   -          pose        output: [[x, y, z], [qx, qy, qz, qw]] (formats.h)
//
// Outcomes: succeeded; preempted.
#pragma once

#include <string>

#include "smachac/robot/robot_state.h"

namespace smachac::robot {

struct ReadEndpointPoseArgs {
  std::string limb{};  ///< empty: input key `limb`
};

class ReadEndpointPoseState : public RobotState {
 public:
  ReadEndpointPoseState(RobotContext& context, ReadEndpointPoseArgs args = {});

 protected:
  std::string run(rt::UserData& userdata) override;

 private:
  ReadEndpointPoseArgs args_;
};

}  // namespace smachac::robot
