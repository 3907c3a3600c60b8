// RobotState: what the Baxter state classes share. Every robot state has SMACHA's Baxter
// outcomes (succeeded, aborted, preempted), works on one RobotContext, and takes each of its
// inputs either from a template variable given to its constructor or, when that is absent,
// from an input key of the same name (so a sub-script can leave `limb` to its caller).
//
// Physical failures (no IK solution, a move that times out, no grasp) end in `aborted`, with
// the reason logged to the context; malformed data (a pose of the wrong shape, an unknown
// limb) throws FormatError, which the runtime reports as the state's failure. Blocking actions
// poll preemptRequested() on every simulation step and end in `preempted`, holding the arm.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "smachac/robot/robot_context.h"
#include "smachac/runtime/state.h"
#include "smachac/runtime/value.h"
#include "smachac/sim/types.h"

namespace smachac::robot {

namespace rt = smachac::runtime;

inline constexpr std::string_view kSucceeded = "succeeded";
inline constexpr std::string_view kAborted = "aborted";

/// Speed and timeout of one arm move; unset fields take the context's defaults.
struct MoveSettings {
  std::optional<double> speed{};    ///< fraction of the joints' velocity limits
  std::optional<double> timeout{};  ///< simulated seconds
};

class RobotState : public rt::State {
 public:
  RobotContext& context() { return context_; }

  /// Returns `preempted` at once when a preempt is already requested, else run().
  std::string execute(rt::UserData& userdata) final;

 protected:
  /// What the state does.
  virtual std::string run(rt::UserData& userdata) = 0;

  /// `inputs` are the input keys this state reads (those without a variable), `outputs`
  /// the keys it writes.
  RobotState(RobotContext& context, rt::Keys inputs, rt::Keys outputs = {});

  sim::World& world() { return context_.world(); }

  /// The limb: the variable when given, else input key `limb`.
  sim::Side limbOf(const std::string& variable, rt::UserData& userdata) const;
  /// The variable when it is not null, else input key `key` (which must be set).
  static rt::Value valueOf(const rt::Value& variable, std::string_view key, rt::UserData& userdata);
  /// The variable when it is not null, else input key `key` when it is set.
  static std::optional<rt::Value> optionalValueOf(const rt::Value& variable, std::string_view key,
                                                  rt::UserData& userdata);

  /// Moves `side`'s arm to `goal`, stepping the world until it gets there, times out, or a
  /// preempt is requested. Returns succeeded, aborted or preempted.
  std::string moveArm(sim::Side side, const sim::JointPositions& goal,
                      const MoveSettings& settings);

  /// Logs `why` and returns `aborted`.
  std::string abort(std::string_view why);
  /// Services the preempt request and returns `preempted`.
  std::string preempted();

 private:
  RobotContext& context_;
};

}  // namespace smachac::robot
