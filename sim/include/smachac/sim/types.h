// Plain value types of the simulation API: vectors, quaternions, poses, limb sides and
// reference frames. They carry no MuJoCo or Eigen types so that callers (robot state classes,
// generated code) need neither.
#pragma once

#include <array>
#include <string_view>

namespace smachac::sim {

/// Number of joints in one Baxter arm, in the order s0, s1, e0, e1, w0, w1, w2.
inline constexpr int kArmJointCount = 7;

/// Joint positions (rad) of one arm, in the order s0, s1, e0, e1, w0, w1, w2.
using JointPositions = std::array<double, kArmJointCount>;

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

/// A unit quaternion, scalar first (ROS messages put w last: mind the order).
struct Quaternion {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

struct Pose {
  Vec3 position{};
  Quaternion orientation{};
};

enum class Side { Left, Right };

/// World is MuJoCo's world frame (floor at z = 0); Base is Baxter's `base` frame, 0.93 m
/// above the floor, in which the demo scripts give their poses.
enum class Frame { World, Base };

/// "left" or "right": the prefix of every joint, actuator and site name of that side.
constexpr std::string_view sideName(Side side) { return side == Side::Left ? "left" : "right"; }

}  // namespace smachac::sim
