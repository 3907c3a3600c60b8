// RobotContext: what every robot state of one program shares. It owns the simulated world
// (created once per program by BaxterBase, see baxter_base.h), the options the program was
// started with, a log for the states' messages and the optional PNG snapshots.
//
// Thread-safe: the two arms of a Concurrence use it at once. Simulated time advances in
// lockstep with the machine's threads: stepUntil() takes the next step only when every
// executing robot state waits for one and, when the context observes the machine's threads
// (attach it with State::setThreadObserver, as runBaxter does), every thread of the machine
// does. So a state that computes (IK, a transition) takes no simulated time, and the arms of a
// Concurrence advance together from the moment it splits, even when the OS starts one child's
// thread late. A thread that stays busy outside robot states for longer than kLateThreadGrace
// of wall time (a state that waits for something else) is not waited for. (The world's own
// mutex is not fair: threads that each step in a loop can starve one another for seconds of
// simulated time.) The log and the snapshotter have a lock each.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/thread_observer.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
class Snapshotter;
}

namespace smachac::robot {

/// Where BaxterBase puts both arms before the machine starts.
enum class StartPose {
  None,     ///< leave them as the scene loads them (q = 0, holding still)
  Neutral,  ///< baxter_interface's move_to_neutral
  Untuck,   ///< tuck_arms.py -u, the pick-and-place demo's start pose
};

struct RobotOptions {
  std::string scene{};         ///< MJCF scene; empty: sim/models/scene.xml
  std::string snapshot_dir{};  ///< write PNG snapshots here; empty: none
  StartPose start_pose = StartPose::None;
  double settle_seconds = 1.0;  ///< simulated time stepped after the machine returns
  bool report = true;           ///< print the final scene report
  std::ostream* log = nullptr;  ///< the states' messages; nullptr: std::cerr
  bool quiet = false;           ///< drop the states' messages (they are still kept)
  sim::MoveOptions move{};      ///< defaults of every arm move (speed, tolerance, timeout)
};

/// How long (wall time) a step waits for a thread of the machine that is not in a robot state.
inline constexpr std::chrono::milliseconds kLateThreadGrace{100};

class RobotContext : public runtime::ThreadObserver {
 public:
  /// A context over an already loaded world (tests build worlds themselves).
  RobotContext(std::unique_ptr<sim::World> world, RobotOptions options = {});
  ~RobotContext();
  RobotContext(const RobotContext&) = delete;
  RobotContext& operator=(const RobotContext&) = delete;

  /// Loads options.scene (or the default scene) and moves to options.start_pose. Never
  /// throws: on failure returns nullptr and sets `error`.
  static std::unique_ptr<RobotContext> create(RobotOptions options, std::string& error);

  sim::World& world() { return *world_; }
  const sim::World& world() const { return *world_; }
  const RobotOptions& options() const { return options_; }

  /// Steps the world until `done()` (checked under the world's lock before each step) or
  /// `timeout` simulated seconds have passed; returns whether `done()` became true. Each step
  /// waits until every executing robot state waits for it too.
  bool stepUntil(const std::function<bool()>& done, double timeout);

  /// A robot state starts or stops executing (RobotState does this; see stepUntil()).
  void beginExecution();
  void endExecution();

  /// runtime::ThreadObserver: the machine's threads (see stepUntil()).
  void split(std::size_t children) override;
  void returned() override;
  void joined() override;

  /// Logs `message` for the state at `path` ("[robot] PICK_BLOCK/OPEN_GRIPPER: ...").
  void log(std::string_view path, std::string_view message);
  /// Every message logged so far, in order.
  std::vector<std::string> messages() const;

  /// Writes `<snapshot_dir>/<NNN>_<label>.png` when snapshots are enabled ('/' in the label
  /// becomes '.'); returns the path, or "" when disabled or failed (failures are logged).
  std::string snapshot(std::string_view label);
  /// The snapshots written so far.
  std::vector<std::string> snapshots() const;

 private:
  std::unique_ptr<sim::World> world_;
  RobotOptions options_;
  std::mutex step_mutex_;
  std::condition_variable step_cv_;
  int executing_ = 0;        ///< robot states executing now
  int threads_ = 1;          ///< threads of the observed machine running now
  int waiting_ = 0;          ///< threads waiting for the next step
  uint64_t generation_ = 0;  ///< steps taken through stepUntil()
  mutable std::mutex log_mutex_;
  std::vector<std::string> messages_;
  mutable std::mutex snapshot_mutex_;
  std::unique_ptr<sim::Snapshotter> snapshotter_;
  std::vector<std::string> snapshots_;
};

}  // namespace smachac::robot
