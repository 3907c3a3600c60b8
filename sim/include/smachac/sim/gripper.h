// One electric parallel gripper: two slide fingers driven by mirrored PD commands, force-limited
// to 20 N each (Baxter's effort). Opening and closing block until the fingers settle; a grasp
// is detected when both pads touch the same free body.
#pragma once

#include <optional>
#include <string>

#include "smachac/sim/types.h"

namespace smachac::sim {

class World;

enum class GripperStatus {
  kOpened,       ///< fingers settled open
  kGrasped,      ///< fingers settled on an object touched by both pads
  kClosedEmpty,  ///< fingers settled closed with nothing between them
  kTimeout,      ///< fingers still moving when the timeout passed
};

struct GripperOptions {
  double timeout = 2.0;  ///< simulated seconds
};

struct GripperResult {
  GripperStatus status = GripperStatus::kTimeout;
  double gap = 0.0;        ///< distance between the pads' inner faces (m)
  std::string heldBody{};  ///< the grasped body, empty unless kGrasped
  /// Opening succeeds with kOpened; closing succeeds with kGrasped.
  auto ok() const -> bool {
    return status == GripperStatus::kOpened || status == GripperStatus::kGrasped;
  }
};

class Gripper {
 public:
  Gripper(World& world, Side side);

  auto side() const -> Side { return side_; }

  /// Blocking: command the fingers open or closed and step until they settle.
  auto open(const GripperOptions& options = {}) -> GripperResult;
  auto close(const GripperOptions& options = {}) -> GripperResult;

  /// Non-blocking forms.
  void commandOpen();
  void commandClose();
  /// Commands the fingers to a fraction of their travel: 0 closed, 1 open (clamped); an
  /// object between them stops them (Baxter's electric gripper's position command).
  void commandOpening(double fraction);

  /// Where the fingers are, as a fraction of their travel: 0 closed, 1 open.
  auto opening() const -> double;
  /// Whether a finger is still moving (faster than the settling threshold).
  auto moving() const -> bool;
  /// The mean force of the finger servos (N, at most 20).
  auto fingerForce() const -> double;

  /// Distance between the pads' inner faces (m): about 35 mm closed, 77 mm open.
  auto gap() const -> double;
  /// The free body (block) that both pads touch, if any: a held block. Poll it to detect a
  /// dropped block.
  auto heldBody() const -> std::optional<std::string>;

  /// Called by World inside each step: writes the finger commands.
  void applyControl();

 private:
  auto waitSettled(const GripperOptions& options) -> bool;
  auto fingerSpeed() const -> double;
  auto resultAfter(bool settled, bool closing) const -> GripperResult;

  World& world_;
  Side side_;
  int fingerQpos_[2] = {-1, -1};
  int fingerDof_[2] = {-1, -1};
  int actuator_[2] = {-1, -1};
  int pad_[2] = {-1, -1};
  double openCommand_[2] = {0.0, 0.0};
  double opening_ = 1.0;  // the commanded fraction of the fingers' travel
};

}  // namespace smachac::sim
