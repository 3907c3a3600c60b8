// The simulated world: one MuJoCo model and its state, the two limbs and grippers that act in
// it, stepping with gravity compensation, time, reset, MuJoCo warnings and the real-time factor.
//
// Every step runs mj_step1, lets each limb and gripper set its servo commands, sets
// qfrc_applied = qfrc_bias on the robot's joints (exact gravity compensation, which MuJoCo 2.2
// has no attribute for) and runs mj_step2. Stepping is serialised by a recursive mutex, so
// blocking calls made from several threads (a Concurrence) advance one shared clock; a single
// thread gets fully deterministic runs.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "smachac/sim/types.h"

struct mjModel_;
struct mjData_;

namespace smachac::sim {

class Gripper;
class Limb;
class World;

/// How many times one MuJoCo warning kind (mjWARN_*) was raised since the last reset.
struct WarningCount {
  std::string name;  ///< e.g. "mjWARN_CONTACTFULL"
  int count = 0;
};

/// The result of World::load: a world, or an error message when the model cannot be used.
struct LoadResult {
  std::unique_ptr<World> world;
  std::string error;
};

class World {
 public:
  /// Loads an MJCF scene that contains the Baxter of sim/models/baxter.xml. Never throws:
  /// a missing file, an XML error or a missing robot part gives `error`.
  static LoadResult load(const std::string& scene_path);
  /// load(defaultScenePath()).
  static LoadResult loadDefault();

  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World();

  /// Back to the model's initial state: time 0, arms at q = 0 holding still, grippers
  /// commanded open, blocks parked, table in place, warnings and timing cleared.
  void reset();

  void step(int count = 1);
  /// Steps for `seconds` of simulated time (rounded to whole steps).
  void stepFor(double seconds);
  /// Steps until `done()` is true (checked before each step) or `timeout` simulated seconds
  /// have passed. Returns whether `done()` became true.
  bool stepUntil(const std::function<bool()>& done, double timeout);

  /// Simulated time (s).
  double time() const;
  double timestep() const;

  Limb& limb(Side side);
  const Limb& limb(Side side) const;
  Gripper& gripper(Side side);
  const Gripper& gripper(Side side) const;

  /// Warning kinds raised since the last reset (none in a healthy run).
  std::vector<WarningCount> warnings() const;
  bool hasWarnings() const;

  /// Simulated seconds per wall-clock second spent stepping since reset() or resetTiming().
  double realTimeFactor() const;
  void resetTiming();

  /// Converts a pose given in `frame` to the world frame, and back.
  Pose toWorld(const Pose& pose, Frame frame) const;
  Pose fromWorld(const Pose& pose, Frame frame) const;

  /// Low-level access for the library and tests. Hold lock() while using data().
  const mjModel_* model() const;
  mjData_* data();
  const mjData_* data() const;
  std::unique_lock<std::recursive_mutex> lock() const;

 private:
  World(mjModel_* model, mjData_* data);
  void stepLocked();
  void applyGravityCompensation();

  mjModel_* model_;
  mjData_* data_;
  std::unique_ptr<Limb> limbs_[2];
  std::unique_ptr<Gripper> grippers_[2];
  std::vector<int> robot_dofs_;
  Pose base_pose_;
  mutable std::recursive_mutex mutex_;
  double wall_seconds_ = 0.0;
  double sim_seconds_ = 0.0;
};

/// Text of every MuJoCo warning printed since the last call (process-wide; MuJoCo has one
/// warning hook). Also keeps MuJoCo from writing MUJOCO_LOG.TXT into the working directory.
std::vector<std::string> takeMujocoMessages();

}  // namespace smachac::sim
