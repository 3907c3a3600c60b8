// PoseToJointTrajServiceState: inverse kinematics, as Baxter's IK service: the joint
// positions that put a limb's endpoint (TCP) at a pose, plus an optional offset (a hover
// pose is the pick pose plus a hover offset). Poses are in Baxter's base frame.
//
//   variable   input key   meaning
//   limb       limb        `left` or `right`
//   poses      poses       the endpoint pose (formats.h; a list holding one pose is accepted)
//   offsets    offsets     optional offset added to the pose (formats.h)
//   -          joints      output: the joint positions, [s0, s1, e0, e1, w0, w1, w2]
//
// The solver starts from the limb's current joints (then standard poses), so the answer
// stays close to the present posture. Outcomes: succeeded; aborted when the pose is out of
// reach (`joints` is not written); preempted.
#pragma once

#include <memory>
#include <string>

#include "smachac/robot/robot_state.h"

namespace smachac::sim {
class Ik;
}

namespace smachac::robot {

struct PoseToJointTrajServiceArgs {
  std::string limb{};   ///< empty: input key `limb`
  rt::Value poses{};    ///< null: input key `poses`
  rt::Value offsets{};  ///< null: input key `offsets`, when set
};

class PoseToJointTrajServiceState : public RobotState {
 public:
  PoseToJointTrajServiceState(RobotContext& context, PoseToJointTrajServiceArgs args = {});
  ~PoseToJointTrajServiceState() override;

 protected:
  std::string run(rt::UserData& userdata) override;

 private:
  PoseToJointTrajServiceArgs args_;
  std::unique_ptr<sim::Ik> ik_;  ///< made on first use; a state runs on one thread at a time
};

}  // namespace smachac::robot
