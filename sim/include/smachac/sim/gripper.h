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
  Opened,       ///< fingers settled open
  Grasped,      ///< fingers settled on an object touched by both pads
  ClosedEmpty,  ///< fingers settled closed with nothing between them
  Timeout,      ///< fingers still moving when the timeout passed
};

struct GripperOptions {
  double timeout = 2.0;  ///< simulated seconds
};

struct GripperResult {
  GripperStatus status = GripperStatus::Timeout;
  double gap = 0.0;         ///< distance between the pads' inner faces (m)
  std::string held_body{};  ///< the grasped body, empty unless Grasped
  /// Opening succeeds with Opened; closing succeeds with Grasped.
  bool ok() const { return status == GripperStatus::Opened || status == GripperStatus::Grasped; }
};

class Gripper {
 public:
  Gripper(World& world, Side side);

  Side side() const { return side_; }

  /// Blocking: command the fingers open or closed and step until they settle.
  GripperResult open(const GripperOptions& options = {});
  GripperResult close(const GripperOptions& options = {});

  /// Non-blocking forms.
  void commandOpen();
  void commandClose();
  /// Commands the fingers to a fraction of their travel: 0 closed, 1 open (clamped); an
  /// object between them stops them (Baxter's electric gripper's position command).
  void commandOpening(double fraction);

  /// Where the fingers are, as a fraction of their travel: 0 closed, 1 open.
  double opening() const;
  /// Whether a finger is still moving (faster than the settling threshold).
  bool moving() const;
  /// The mean force of the finger servos (N, at most 20).
  double fingerForce() const;

  /// Distance between the pads' inner faces (m): about 35 mm closed, 77 mm open.
  double gap() const;
  /// The free body (block) that both pads touch, if any: a held block. Poll it to detect a
  /// dropped block.
  std::optional<std::string> heldBody() const;

  /// Called by World inside each step: writes the finger commands.
  void applyControl();

 private:
  bool waitSettled(const GripperOptions& options);
  double fingerSpeed() const;
  GripperResult resultAfter(bool settled, bool closing) const;

  World& world_;
  Side side_;
  int finger_qpos_[2] = {-1, -1};
  int finger_dof_[2] = {-1, -1};
  int actuator_[2] = {-1, -1};
  int pad_[2] = {-1, -1};
  double open_command_[2] = {0.0, 0.0};
  double opening_ = 1.0;  // the commanded fraction of the fingers' travel
};

}  // namespace smachac::sim
