// Inverse kinematics for a Baxter arm: damped least squares on MuJoCo's site Jacobian of the
// TCP, computed on a scratch mjData (the world's state is never touched), with joint-limit
// clamping and several seeds. A pose out of reach gives IkStatus::kUnreachable, never a
// partial answer.
#pragma once

#include <span>
#include <vector>

#include "smachac/sim/types.h"

struct mjData_;

namespace smachac::sim {

class World;

enum class IkStatus {
  kSolved,         ///< within both tolerances
  kUnreachable,    ///< no seed converged: the pose is out of reach (or too close to a limit)
  kInvalidTarget,  ///< the target has non-finite values or a zero quaternion
};

struct IkOptions {
  double positionTolerance = 1e-4;     ///< m
  double orientationTolerance = 1e-3;  ///< rad
  int maxIterations = 150;             ///< per seed
  double damping = 0.02;               ///< lambda of damped least squares
  double maxStep = 0.3;                ///< rad, largest joint change per iteration
};

struct IkResult {
  IkStatus status = IkStatus::kUnreachable;
  JointPositions joints{};  ///< the solution; the best attempt when unreachable
  double positionError = 0.0;
  double orientationError = 0.0;
  int iterations = 0;  ///< over all seeds tried
  auto ok() const -> bool { return status == IkStatus::kSolved; }
};

class Ik {
 public:
  explicit Ik(const World& world);
  Ik(const Ik&) = delete;
  auto operator=(const Ik&) -> Ik& = delete;
  ~Ik();

  /// Joint positions that put `side`'s TCP at `target` (given in `frame`). Seeds, in order:
  /// the limb's current positions, untuck, neutral, then fixed spread-out poses; the first
  /// seed that converges wins, so the answer stays close to the current posture.
  auto solve(Side side, const Pose& target, Frame frame = Frame::kBase,
             const IkOptions& options = {}) -> IkResult;

  /// The same with caller-chosen seeds (target in the world frame).
  auto solveFromSeeds(Side side, const Pose& worldTarget, std::span<const JointPositions> seeds,
                      const IkOptions& options) -> IkResult;

  /// Forward kinematics: the TCP pose (world frame) for joint positions.
  auto forward(Side side, const JointPositions& joints) -> Pose;

 private:
  auto seedsFor(Side side) const -> std::vector<JointPositions>;

  const World& world_;
  mjData_* scratch_;
};

}  // namespace smachac::sim
