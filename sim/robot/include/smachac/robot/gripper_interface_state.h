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
  std::string run(rt::UserData& userdata) override;

 private:
  /// Commands the fingers and steps until they settle; nothing when preempted.
  std::optional<sim::GripperResult> actuate(sim::Gripper& gripper, bool close);
  static sim::GripperResult outcome(const sim::Gripper& gripper, bool settled, bool close);
  std::string judge(const sim::GripperResult& result, bool close);

  GripperInterfaceArgs args_;
};

}  // namespace smachac::robot
