// Ik: damped least squares on mj_jacSite over a scratch mjData, several seeds, clamped to
// the joint limits.
#include "smachac/sim/ik.h"

#include <mujoco/mujoco.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "pose_math.h"
#include "robot_names.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/standard_poses.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

using Matrix6x7 = Eigen::Matrix<double, 6, kArmJointCount>;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Vector7 = Eigen::Matrix<double, kArmJointCount, 1>;

// Where one arm lives in the model.
struct ArmIndex {
  int site = -1;
  std::array<int, kArmJointCount> qpos{};
  std::array<int, kArmJointCount> dof{};
};

ArmIndex armIndex(const mjModel* model, Side side) {
  ArmIndex arm;
  arm.site = detail::objectId(model, mjOBJ_SITE, detail::tcpSiteName(side));
  for (int i = 0; i < kArmJointCount; ++i) {
    const int joint = detail::objectId(model, mjOBJ_JOINT, detail::armJointName(side, i));
    arm.qpos[static_cast<size_t>(i)] = model->jnt_qposadr[joint];
    arm.dof[static_cast<size_t>(i)] = model->jnt_dofadr[joint];
  }
  return arm;
}

// One solver run from one seed on the scratch data.
class DlsRun {
 public:
  DlsRun(const mjModel* model, mjData* data, const ArmIndex& arm, const Limb& limb)
      : model_(model),
        data_(data),
        arm_(arm),
        limb_(limb),
        jacp_(static_cast<size_t>(3 * model->nv)),
        jacr_(static_cast<size_t>(3 * model->nv)) {}

  bool run(const Pose& target, JointPositions q, const IkOptions& options, IkResult& out) {
    const Eigen::Vector3d target_position = detail::toEigen(target.position);
    const Eigen::Quaterniond target_orientation = detail::toEigen(target.orientation);
    for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
      setJoints(q);
      const Vector6 error = poseError(target_position, target_orientation);
      out.joints = q;
      out.position_error = error.head<3>().norm();
      out.orientation_error = error.tail<3>().norm();
      ++out.iterations;
      if (out.position_error <= options.position_tolerance &&
          out.orientation_error <= options.orientation_tolerance) {
        return true;
      }
      q = clampToLimits(addStep(q, dampedStep(error, options)));
    }
    return false;
  }

  void setJoints(const JointPositions& q) {
    for (size_t i = 0; i < q.size(); ++i) data_->qpos[arm_.qpos[i]] = q[i];
    mj_kinematics(model_, data_);
    mj_comPos(model_, data_);
  }

 private:
  Vector6 poseError(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) const {
    const Pose current =
        detail::poseFromMujoco(data_->site_xpos + 3 * arm_.site, data_->site_xmat + 9 * arm_.site);
    Vector6 error;
    error.head<3>() = position - detail::toEigen(current.position);
    error.tail<3>() = detail::orientationError(orientation, detail::toEigen(current.orientation));
    return error;
  }

  Vector7 dampedStep(const Vector6& error, const IkOptions& options) {
    mj_jacSite(model_, data_, jacp_.data(), jacr_.data(), arm_.site);
    Matrix6x7 jacobian;
    for (int c = 0; c < kArmJointCount; ++c) {
      const int dof = arm_.dof[static_cast<size_t>(c)];
      for (int r = 0; r < 3; ++r) {
        jacobian(r, c) = jacp_[static_cast<size_t>(r * model_->nv + dof)];
        jacobian(r + 3, c) = jacr_[static_cast<size_t>(r * model_->nv + dof)];
      }
    }
    const double lambda2 = options.damping * options.damping;
    const Eigen::Matrix<double, 6, 6> jjt =
        jacobian * jacobian.transpose() + lambda2 * Eigen::Matrix<double, 6, 6>::Identity();
    Vector7 step = jacobian.transpose() * jjt.ldlt().solve(error);
    const double largest = step.cwiseAbs().maxCoeff();
    if (largest > options.max_step) step *= options.max_step / largest;
    return step;
  }

  static JointPositions addStep(JointPositions q, const Vector7& step) {
    for (size_t i = 0; i < q.size(); ++i) q[i] += step(static_cast<Eigen::Index>(i));
    return q;
  }

  JointPositions clampToLimits(JointPositions q) const {
    for (size_t i = 0; i < q.size(); ++i) {
      q[i] = std::clamp(q[i], limb_.lowerLimits()[i], limb_.upperLimits()[i]);
    }
    return q;
  }

  const mjModel* model_;
  mjData* data_;
  const ArmIndex& arm_;
  const Limb& limb_;
  std::vector<double> jacp_;
  std::vector<double> jacr_;
};

// Fixed, spread-out seeds for the left arm (mirrored for the right): elbow up and down,
// wrist turned, reaching near and far.
constexpr std::array<JointPositions, 4> kExtraLeftSeeds = {{
    {0.3, -0.3, -1.5, 1.5, 1.2, 1.2, -1.0},
    {-0.5, -0.6, 0.0, 1.8, 0.0, 0.4, 0.0},
    {0.0, 0.2, -2.0, 0.8, 2.0, 1.5, -1.5},
    {-0.8, -1.2, 1.0, 2.2, -1.0, 1.0, 1.0},
}};

}  // namespace

Ik::Ik(const World& world) : world_(world), scratch_(mj_makeData(world.model())) {}

Ik::~Ik() { mj_deleteData(scratch_); }

std::vector<JointPositions> Ik::seedsFor(Side side) const {
  std::vector<JointPositions> seeds = {world_.limb(side).jointPositions(), untuckPose(side),
                                       neutralPose(side)};
  for (const JointPositions& left : kExtraLeftSeeds) {
    seeds.push_back(side == Side::Left ? left : mirrorPose(left));
  }
  return seeds;
}

IkResult Ik::solve(Side side, const Pose& target, Frame frame, const IkOptions& options) {
  if (!detail::isValidPose(target)) return {.status = IkStatus::InvalidTarget};
  const std::vector<JointPositions> seeds = seedsFor(side);
  return solveFromSeeds(side, world_.toWorld(detail::normalized(target), frame), seeds, options);
}

IkResult Ik::solveFromSeeds(Side side, const Pose& world_target,
                            std::span<const JointPositions> seeds, const IkOptions& options) {
  if (!detail::isValidPose(world_target)) return {.status = IkStatus::InvalidTarget};
  const Pose target = detail::normalized(world_target);
  const ArmIndex arm = armIndex(world_.model(), side);
  DlsRun solver(world_.model(), scratch_, arm, world_.limb(side));
  IkResult best;
  best.position_error = std::numeric_limits<double>::infinity();
  int iterations = 0;
  for (const JointPositions& seed : seeds) {
    IkResult attempt;
    const bool solved = solver.run(target, seed, options, attempt);
    iterations += attempt.iterations;
    if (solved) attempt.status = IkStatus::Solved;
    if (solved || attempt.position_error < best.position_error) best = attempt;
    if (solved) break;
  }
  best.iterations = iterations;
  return best;
}

Pose Ik::forward(Side side, const JointPositions& joints) {
  const ArmIndex arm = armIndex(world_.model(), side);
  DlsRun solver(world_.model(), scratch_, arm, world_.limb(side));
  solver.setJoints(joints);
  return detail::poseFromMujoco(scratch_->site_xpos + 3 * arm.site,
                                scratch_->site_xmat + 9 * arm.site);
}

}  // namespace smachac::sim
