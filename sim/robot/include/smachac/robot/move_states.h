// The joint-space motion states.
//
// MoveToJointPositionsState: moves a limb to joint positions (baxter_interface's
// move_to_joint_positions: a smooth joint-space move, then within tolerance of the goal).
//
//   variable   input key   meaning
//   limb       limb        `left` or `right`
//   positions  positions   joint positions (formats.h)
//   speed      -           fraction of the joint velocity limits (default: the context's, 0.3)
//   timeout    -           simulated seconds (default: the context's, 15)
//
// FollowJointTrajActionState: moves a limb through a list of joint waypoints in order (what
// the follow-joint-trajectory action server does), each move as above.
//
//   variable   input key   meaning
//   limb       limb        `left` or `right`
//   points     points      a list of joint positions
//   speed, timeout         per waypoint, as above
//
// Outcomes: succeeded; aborted when a goal lies outside the joint limits or a move times out;
// preempted (the arm holds where it is).
#pragma once

#include <optional>
#include <string>

#include "smachac/robot/robot_state.h"

namespace smachac::robot {

struct MoveToJointPositionsArgs {
  std::string limb{};     ///< empty: input key `limb`
  rt::Value positions{};  ///< null: input key `positions`
  std::optional<double> speed{};
  std::optional<double> timeout{};
};

class MoveToJointPositionsState : public RobotState {
 public:
  MoveToJointPositionsState(RobotContext& context, MoveToJointPositionsArgs args = {});

 protected:
  std::string run(rt::UserData& userdata) override;

 private:
  MoveToJointPositionsArgs args_;
};

struct FollowJointTrajActionArgs {
  std::string limb{};  ///< empty: input key `limb`
  rt::Value points{};  ///< null: input key `points`
  std::optional<double> speed{};
  std::optional<double> timeout{};
};

class FollowJointTrajActionState : public RobotState {
 public:
  FollowJointTrajActionState(RobotContext& context, FollowJointTrajActionArgs args = {});

 protected:
  std::string run(rt::UserData& userdata) override;

 private:
  FollowJointTrajActionArgs args_;
};

}  // namespace smachac::robot
