// The MJCF names of the robot parts and the check that a model has them.
#include "robot_names.h"

#include <mujoco/mujoco.h>

#include <array>
#include <string_view>

namespace smachac::sim::detail {
namespace {

constexpr std::array<std::string_view, kArmJointCount> kJointSuffixes = {"s0", "s1", "e0", "e1",
                                                                         "w0", "w1", "w2"};

std::string prefix(Side side) { return std::string(sideName(side)) + "_"; }

std::string fingerLetter(int finger) { return finger == 0 ? "l" : "r"; }

}  // namespace

std::string armJointName(Side side, int index) {
  return prefix(side) + std::string(kJointSuffixes.at(static_cast<size_t>(index)));
}

std::string fingerJointName(Side side, int finger) {
  return fingerActuatorName(side, finger) + "_joint";
}

std::string fingerActuatorName(Side side, int finger) {
  return prefix(side) + "gripper_" + fingerLetter(finger) + "_finger";
}

std::string padGeomName(Side side, int finger) {
  return prefix(side) + "gripper_" + fingerLetter(finger) + "_pad";
}

std::string tcpSiteName(Side side) { return prefix(side) + "gripper"; }

int objectId(const mjModel_* model, int type, const std::string& name) {
  return mj_name2id(model, type, name.c_str());
}

std::string checkRobotNames(const mjModel_* model) {
  auto missing = [&](int type, const std::string& name, const char* what) -> std::string {
    return objectId(model, type, name) < 0 ? "model has no " + std::string(what) + " `" + name + "`"
                                           : "";
  };
  std::string error = missing(mjOBJ_BODY, kBaseBody, "body");
  for (Side side : {Side::Left, Side::Right}) {
    for (int i = 0; i < kArmJointCount && error.empty(); ++i) {
      error = missing(mjOBJ_JOINT, armJointName(side, i), "joint");
      if (error.empty()) error = missing(mjOBJ_ACTUATOR, armJointName(side, i), "actuator");
    }
    for (int f = 0; f < 2 && error.empty(); ++f) {
      error = missing(mjOBJ_JOINT, fingerJointName(side, f), "joint");
      if (error.empty()) error = missing(mjOBJ_ACTUATOR, fingerActuatorName(side, f), "actuator");
      if (error.empty()) error = missing(mjOBJ_GEOM, padGeomName(side, f), "geom");
    }
    if (error.empty()) error = missing(mjOBJ_SITE, tcpSiteName(side), "site");
  }
  return error;
}

}  // namespace smachac::sim::detail
