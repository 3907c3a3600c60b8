// Limb: joint PD servos with velocity feed-forward along quintic joint-space moves.
#include "smachac/sim/limb.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>

#include "pose_math.h"
#include "robot_names.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

// URDF velocity limits (rad/s) of s0 s1 e0 e1 w0 w1 w2: MJCF has no such attribute.
constexpr JointPositions kVelocityLimits = {1.5, 1.5, 1.5, 1.5, 4.0, 4.0, 4.0};
constexpr double kShortestMove = 0.5;   // s
constexpr double kLimitSlack = 1e-6;    // rad a goal may lie outside a limit (then clamped)
constexpr double kQuinticPeak = 1.875;  // peak / mean speed of the minimum-jerk profile
// Streaming mode: the target's speed changes by at most the joint's speed limit over
// kStreamRampTime (s); it is never more than lets it stop at the goal, and closes the last
// of the distance with the time constant kStreamTimeConstant (s).
constexpr double kStreamRampTime = 0.6;
constexpr double kStreamTimeConstant = 0.05;

// Minimum-jerk profile: position fraction and its time derivative (per unit duration).
std::pair<double, double> quintic(double s) {
  s = std::clamp(s, 0.0, 1.0);
  const double s3 = s * s * s;
  return {s3 * (10.0 - 15.0 * s + 6.0 * s * s), 30.0 * s * s * (1.0 - 2.0 * s + s * s)};
}

size_t index(int i) { return static_cast<size_t>(i); }

}  // namespace

Limb::Limb(World& world, Side side) : world_(world), side_(side) {
  const mjModel* model = world_.model();
  for (int i = 0; i < kArmJointCount; ++i) {
    const std::string name = detail::armJointName(side, i);
    const int joint = detail::objectId(model, mjOBJ_JOINT, name);
    actuator_[index(i)] = detail::objectId(model, mjOBJ_ACTUATOR, name);
    qpos_address_[index(i)] = model->jnt_qposadr[joint];
    dof_address_[index(i)] = model->jnt_dofadr[joint];
    lower_[index(i)] = model->jnt_range[2 * joint];
    upper_[index(i)] = model->jnt_range[2 * joint + 1];
    velocity_limit_[index(i)] = kVelocityLimits[index(i)];
    const int a = actuator_[index(i)];
    lead_time_[index(i)] =
        -model->actuator_biasprm[a * mjNBIAS + 2] / model->actuator_gainprm[a * mjNGAIN];
  }
  site_ = detail::objectId(model, mjOBJ_SITE, detail::tcpSiteName(side));
}

std::array<std::string, kArmJointCount> Limb::jointNames() const {
  std::array<std::string, kArmJointCount> names;
  for (int i = 0; i < kArmJointCount; ++i) names[index(i)] = detail::armJointName(side_, i);
  return names;
}

JointPositions Limb::jointPositions() const {
  auto guard = world_.lock();
  JointPositions q{};
  for (size_t i = 0; i < q.size(); ++i) q[i] = world_.data()->qpos[qpos_address_[i]];
  return q;
}

JointPositions Limb::jointVelocities() const {
  auto guard = world_.lock();
  JointPositions v{};
  for (size_t i = 0; i < v.size(); ++i) v[i] = world_.data()->qvel[dof_address_[i]];
  return v;
}

Pose Limb::endpointPose(Frame frame) const {
  auto guard = world_.lock();
  const mjData* data = world_.data();
  const Pose world =
      detail::poseFromMujoco(data->site_xpos + 3 * site_, data->site_xmat + 9 * site_);
  return world_.fromWorld(world, frame);
}

bool Limb::validGoal(const JointPositions& goal) const {
  for (size_t i = 0; i < goal.size(); ++i) {
    if (!std::isfinite(goal[i])) return false;
    if (goal[i] < lower_[i] - kLimitSlack || goal[i] > upper_[i] + kLimitSlack) return false;
  }
  return true;
}

double Limb::moveDuration(const JointPositions& from, const JointPositions& to,
                          double speed) const {
  double duration = kShortestMove;
  const double fraction = std::clamp(speed, 0.01, 1.0);
  for (size_t i = 0; i < from.size(); ++i) {
    const double needed =
        kQuinticPeak * std::abs(to[i] - from[i]) / (fraction * velocity_limit_[i]);
    duration = std::max(duration, needed);
  }
  return duration;
}

bool Limb::startMove(const JointPositions& goal, const MoveOptions& options) {
  if (!validGoal(goal)) return false;
  auto guard = world_.lock();
  start_ = jointPositions();
  for (size_t i = 0; i < goal.size(); ++i) goal_[i] = std::clamp(goal[i], lower_[i], upper_[i]);
  start_time_ = world_.time();
  end_time_ = start_time_ + moveDuration(start_, goal_, options.speed);
  tolerance_ = options.tolerance;
  streaming_ = false;
  return true;
}

double Limb::moveError() const {
  const JointPositions q = jointPositions();
  double error = 0.0;
  for (size_t i = 0; i < q.size(); ++i) error = std::max(error, std::abs(goal_[i] - q[i]));
  return error;
}

bool Limb::moveDone() const {
  auto guard = world_.lock();
  return world_.time() >= end_time_ && moveError() <= tolerance_;
}

MoveResult Limb::moveToJointPositions(const JointPositions& goal, const MoveOptions& options) {
  MoveResult result;
  if (!startMove(goal, options)) {
    result.status = MoveStatus::InvalidTarget;
    return result;
  }
  const double begin = world_.time();
  const bool reached = world_.stepUntil([this] { return moveDone(); }, options.timeout);
  result.status = reached ? MoveStatus::Reached : MoveStatus::Timeout;
  result.max_error = moveError();
  result.duration = world_.time() - begin;
  return result;
}

void Limb::holdCurrent() {
  auto guard = world_.lock();
  start_ = goal_ = jointPositions();
  start_time_ = end_time_ = world_.time();
  streaming_ = false;
}

bool Limb::commandPositions(const JointPositions& goal, double speed) {
  if (!validGoal(goal) || !std::isfinite(speed)) return false;
  auto guard = world_.lock();
  if (!streaming_) {
    stream_target_ = jointPositions();
    stream_velocity_ = {};
    stream_time_ = world_.time();
  }
  for (size_t i = 0; i < goal.size(); ++i) goal_[i] = std::clamp(goal[i], lower_[i], upper_[i]);
  stream_speed_ = std::clamp(speed, 0.01, 1.0);
  streaming_ = true;
  return true;
}

void Limb::applyStreamControl(double time) {
  const double dt = std::max(0.0, time - stream_time_);
  stream_time_ = time;
  mjData* data = world_.data();
  for (size_t i = 0; i < goal_.size(); ++i) {
    const double limit = stream_speed_ * velocity_limit_[i];
    const double acceleration = limit / kStreamRampTime;
    const double error = goal_[i] - stream_target_[i];
    const double stoppable = std::min(limit, std::sqrt(2.0 * acceleration * std::abs(error)));
    const double wanted = std::clamp(error / kStreamTimeConstant, -stoppable, stoppable);
    const double ramp = acceleration * dt;
    stream_velocity_[i] += std::clamp(wanted - stream_velocity_[i], -ramp, ramp);
    stream_target_[i] += stream_velocity_[i] * dt;
    data->ctrl[actuator_[i]] = stream_target_[i] + lead_time_[i] * stream_velocity_[i];
  }
}

void Limb::applyControl(double time) {
  if (streaming_) return applyStreamControl(time);
  const double duration = end_time_ - start_time_;
  const double s = duration > 0.0 ? (time - start_time_) / duration : 1.0;
  const auto [fraction, rate] = quintic(s);
  mjData* data = world_.data();
  for (size_t i = 0; i < goal_.size(); ++i) {
    const double delta = goal_[i] - start_[i];
    const double velocity = s < 1.0 && duration > 0.0 ? delta * rate / duration : 0.0;
    data->ctrl[actuator_[i]] = start_[i] + delta * fraction + lead_time_[i] * velocity;
  }
}

}  // namespace smachac::sim
