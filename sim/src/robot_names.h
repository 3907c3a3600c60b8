// The MJCF names the library relies on (sim/models/baxter.xml), in one place, and the check
// that a loaded model has them all.
#pragma once

#include <string>

#include "smachac/sim/types.h"

struct mjModel_;

namespace smachac::sim::detail {

/// "left_s0" ... "left_w2" for index 0..6.
std::string armJointName(Side side, int index);
/// "left_gripper_l_finger_joint" (finger 0) or "left_gripper_r_finger_joint" (finger 1).
std::string fingerJointName(Side side, int finger);
/// "left_gripper_l_finger" / "left_gripper_r_finger": the finger actuators.
std::string fingerActuatorName(Side side, int finger);
/// "left_gripper_l_pad" / "left_gripper_r_pad".
std::string padGeomName(Side side, int finger);
/// "left_gripper": the TCP site.
std::string tcpSiteName(Side side);
/// The robot's root body.
inline constexpr const char* kBaseBody = "base";

/// Id of a named MuJoCo object (mjOBJ_*), -1 if absent.
int objectId(const mjModel_* model, int type, const std::string& name);

/// "" when every name above exists (arm joints with actuators of the same name); otherwise
/// a message listing the first missing one.
std::string checkRobotNames(const mjModel_* model);

}  // namespace smachac::sim::detail
