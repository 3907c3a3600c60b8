// The MJCF names the library relies on (sim/models/baxter.xml), in one place, and the check
// that a loaded model has them all.
#pragma once

#include <string>

#include "smachac/sim/types.h"

struct mjModel_;

namespace smachac::sim::detail {

/// "left_s0" ... "left_w2" for index 0..6.
auto armJointName(Side side, int index) -> std::string;
/// "left_gripper_l_finger_joint" (finger 0) or "left_gripper_r_finger_joint" (finger 1).
auto fingerJointName(Side side, int finger) -> std::string;
/// "left_gripper_l_finger" / "left_gripper_r_finger": the finger actuators.
auto fingerActuatorName(Side side, int finger) -> std::string;
/// "left_gripper_l_pad" / "left_gripper_r_pad".
auto padGeomName(Side side, int finger) -> std::string;
/// "left_gripper": the TCP site.
auto tcpSiteName(Side side) -> std::string;
/// The robot's root body.
inline constexpr const char* kBaseBody = "base";

/// Id of a named MuJoCo object (mjOBJ_*), -1 if absent.
auto objectId(const mjModel_* model, int type, const std::string& name) -> int;

/// "" when every name above exists (arm joints with actuators of the same name); otherwise
/// a message listing the first missing one.
auto checkRobotNames(const mjModel_* model) -> std::string;

}  // namespace smachac::sim::detail
