// GripperInterfaceState: opens or closes a limb's electric gripper and waits until the
// fingers settle.
//
//   variable      input key   meaning
//   limb          limb        `left` or `right`
//   command       command     `open` or `close`
//   expect_grasp  -           closing must grasp an object (default true)
//   timeout       -           simulated seconds for the fingers to settle (default 2)
//
// Outcomes: succeeded; aborted when the fingers do not settle, or when closing was expected
// to grasp an object and closed on nothing; preempted. Takes a snapshot when it succeeds
// (if snapshots are enabled).
#pragma once

#include <optional>
#include <string>

#include "smachac/robot/robot_state.h"

namespace smachac::sim {
class Gripper;
struct GripperResult;
}  // namespace smachac::sim

namespace smachac::robot {

struct GripperInterfaceArgs {
  std::string limb{};     ///< empty: input key `limb`
  std::string command{};  ///< empty: input key `command`
  bool expect_grasp = true;
  double timeout = 2.0;
};

class GripperInterfaceState : public RobotState {
 public:
  GripperInterfaceState(RobotContext& context, GripperInterfaceArgs args = {});

 protected:
  auto run(rt::UserData& userdata) -> std::string override;

 private:
  /// Commands the fingers and steps until they settle; nothing when preempted.
  auto actuate(sim::Gripper& gripper, bool close) -> std::optional<sim::GripperResult>;
  static auto outcome(const sim::Gripper& gripper, bool settled, bool close) -> sim::GripperResult;
  auto judge(const sim::GripperResult& result, bool close) -> std::string;

  GripperInterfaceArgs args_;
};

}  // namespace smachac::robot
