// Inverse kinematics for a Baxter arm: damped least squares on MuJoCo's site Jacobian of the
// TCP, computed on a scratch mjData (the world's state is never touched), with joint-limit
// clamping and several seeds. A pose out of reach gives IkStatus::Unreachable, never a
// partial answer.
#pragma once

#include <span>
#include <vector>

#include "smachac/sim/types.h"

struct mjData_;

namespace smachac::sim {

class World;

enum class IkStatus {
  Solved,         ///< within both tolerances
  Unreachable,    ///< no seed converged: the pose is out of reach (or too close to a limit)
  InvalidTarget,  ///< the target has non-finite values or a zero quaternion
};

struct IkOptions {
  double position_tolerance = 1e-4;     ///< m
  double orientation_tolerance = 1e-3;  ///< rad
  int max_iterations = 150;             ///< per seed
  double damping = 0.02;                ///< lambda of damped least squares
  double max_step = 0.3;                ///< rad, largest joint change per iteration
};

struct IkResult {
  IkStatus status = IkStatus::Unreachable;
  JointPositions joints{};  ///< the solution; the best attempt when unreachable
  double position_error = 0.0;
  double orientation_error = 0.0;
  int iterations = 0;  ///< over all seeds tried
  bool ok() const { return status == IkStatus::Solved; }
};

class Ik {
 public:
  explicit Ik(const World& world);
  Ik(const Ik&) = delete;
  Ik& operator=(const Ik&) = delete;
  ~Ik();

  /// Joint positions that put `side`'s TCP at `target` (given in `frame`). Seeds, in order:
  /// the limb's current positions, untuck, neutral, then fixed spread-out poses; the first
  /// seed that converges wins, so the answer stays close to the current posture.
  IkResult solve(Side side, const Pose& target, Frame frame = Frame::Base,
                 const IkOptions& options = {});

  /// The same with caller-chosen seeds (target in the world frame).
  IkResult solveFromSeeds(Side side, const Pose& world_target,
                          std::span<const JointPositions> seeds, const IkOptions& options);

  /// Forward kinematics: the TCP pose (world frame) for joint positions.
  Pose forward(Side side, const JointPositions& joints);

 private:
  std::vector<JointPositions> seedsFor(Side side) const;

  const World& world_;
  mjData_* scratch_;
};

}  // namespace smachac::sim
