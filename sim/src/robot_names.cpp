// The MJCF names of the robot parts and the check that a model has them.
#include "robot_names.h"

#include <mujoco/mujoco.h>

#include <array>
#include <string_view>

namespace smachac::sim::detail {
namespace {

constexpr std::array<std::string_view, kArmJointCount> kJointSuffixes = {"s0", "s1", "e0", "e1",
                                                                         "w0", "w1", "w2"};

auto prefix(Side side) -> std::string { return std::string(sideName(side)) + "_"; }

auto fingerLetter(int finger) -> std::string { return finger == 0 ? "l" : "r"; }

}  // namespace

auto armJointName(Side side, int index) -> std::string {
  return prefix(side) + std::string(kJointSuffixes.at(static_cast<size_t>(index)));
}

auto fingerJointName(Side side, int finger) -> std::string {
  return fingerActuatorName(side, finger) + "_joint";
}

auto fingerActuatorName(Side side, int finger) -> std::string {
  return prefix(side) + "gripper_" + fingerLetter(finger) + "_finger";
}

auto padGeomName(Side side, int finger) -> std::string {
  return prefix(side) + "gripper_" + fingerLetter(finger) + "_pad";
}

auto tcpSiteName(Side side) -> std::string { return prefix(side) + "gripper"; }

auto objectId(const mjModel_* model, int type, const std::string& name) -> int {
  return mj_name2id(model, type, name.c_str());
}

auto checkRobotNames(const mjModel_* model) -> std::string {
  auto missing = [&](int type, const std::string& name, const char* what) -> std::string {
    return objectId(model, type, name) < 0 ? "model has no " + std::string(what) + " `" + name + "`"
                                           : "";
  };
  std::string error = missing(mjOBJ_BODY, kBaseBody, "body");
  for (Side side : {Side::kLeft, Side::kRight}) {
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
