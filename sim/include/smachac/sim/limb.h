// One Baxter arm: its seven joint PD servos (force-limited to the URDF efforts), smooth
// joint-space moves with a tolerance and a timeout, joint readings and the endpoint (TCP) pose.
//
// A move follows a quintic (minimum-jerk) profile from the current positions to the goal; its
// duration keeps every joint under `speed` times its velocity limit. The servo command carries
// velocity feed-forward, so tracking lag stays small. A move succeeds when the profile has
// ended and every joint is within `tolerance` of the goal, and times out otherwise.
#pragma once

#include <array>
#include <string>

#include "smachac/sim/types.h"

namespace smachac::sim {

class World;

enum class MoveStatus {
  Reached,        ///< every joint within tolerance of the goal
  Timeout,        ///< the goal was not reached within the timeout
  InvalidTarget,  ///< a goal value is not finite or lies outside the joint limits
};

struct MoveOptions {
  double speed = 0.3;              ///< fraction of each joint's velocity limit (Baxter's default)
  double tolerance = 0.008726646;  ///< rad, per joint (baxter_interface's default)
  double timeout = 15.0;           ///< simulated seconds
};

struct MoveResult {
  MoveStatus status = MoveStatus::Timeout;
  double max_error = 0.0;  ///< largest |goal - q| at the end (rad)
  double duration = 0.0;   ///< simulated seconds spent
  bool ok() const { return status == MoveStatus::Reached; }
};

class Limb {
 public:
  Limb(World& world, Side side);

  Side side() const { return side_; }
  /// "left_s0" ... "left_w2" (or right_*).
  std::array<std::string, kArmJointCount> jointNames() const;
  const JointPositions& lowerLimits() const { return lower_; }
  const JointPositions& upperLimits() const { return upper_; }

  JointPositions jointPositions() const;
  JointPositions jointVelocities() const;
  /// The TCP site (`<side>_gripper`, 0.27125 m beyond w2) in `frame`.
  Pose endpointPose(Frame frame = Frame::Base) const;

  /// Moves to `goal` and blocks (stepping the world) until reached or timed out.
  MoveResult moveToJointPositions(const JointPositions& goal, const MoveOptions& options = {});

  /// Non-blocking form: starts the move and returns false (doing nothing) for an invalid goal.
  /// Step the world and poll moveDone(); several limbs can move at once this way.
  bool startMove(const JointPositions& goal, const MoveOptions& options = {});
  bool moveDone() const;
  /// Largest |goal - q| of the current move (rad).
  double moveError() const;

  /// Holds the current positions (cancels a move).
  void holdCurrent();

  /// Streaming position mode, as Baxter's joint position controller: the servo target
  /// approaches `goal` no faster than `speed` times each joint's velocity limit, speeding up
  /// and slowing down smoothly, then holds it. A new command replaces the goal at once (cancels
  /// a move); returns false, doing nothing, for an invalid goal.
  bool commandPositions(const JointPositions& goal, double speed);

  /// Called by World inside each step: writes the servo commands for the current time.
  void applyControl(double time);

 private:
  bool validGoal(const JointPositions& goal) const;
  double moveDuration(const JointPositions& from, const JointPositions& to, double speed) const;
  void applyStreamControl(double time);

  World& world_;
  Side side_;
  std::array<int, kArmJointCount> qpos_address_{};
  std::array<int, kArmJointCount> dof_address_{};
  std::array<int, kArmJointCount> actuator_{};
  JointPositions lower_{};
  JointPositions upper_{};
  JointPositions velocity_limit_{};
  JointPositions lead_time_{};  // kv / kp of each servo: velocity feed-forward
  int site_ = -1;
  // The current move: a quintic profile from start_ to goal_ over [startTime_, endTime_].
  JointPositions start_{};
  JointPositions goal_{};
  double start_time_ = 0.0;
  double end_time_ = 0.0;
  double tolerance_ = 0.008726646;
  // Streaming mode (commandPositions): the servo target, its velocity and its speed fraction.
  bool streaming_ = false;
  JointPositions stream_target_{};
  JointPositions stream_velocity_{};
  double stream_speed_ = 0.3;
  double stream_time_ = 0.0;
};

}  // namespace smachac::sim
