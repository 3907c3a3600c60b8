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
  virtual auto run(rt::UserData& userdata) -> std::string = 0;

  /// `inputs` are the input keys this state reads (those without a variable), `outputs`
  /// the keys it writes.
  RobotState(RobotContext& context, rt::Keys inputs, rt::Keys outputs = {});

  auto world() -> sim::World& { return context_.world(); }

  /// The limb: the variable when given, else input key `limb`.
  auto limbOf(const std::string& variable, rt::UserData& userdata) const -> sim::Side;
  /// The variable when it is not null, else input key `key` (which must be set).
  static auto valueOf(const rt::Value& variable, std::string_view key, rt::UserData& userdata)
      -> rt::Value;
  /// The variable when it is not null, else input key `key` when it is set.
  static auto optionalValueOf(const rt::Value& variable, std::string_view key,
                              rt::UserData& userdata) -> std::optional<rt::Value>;

  /// Moves `side`'s arm to `goal`, stepping the world until it gets there, times out, or a
  /// preempt is requested. Returns succeeded, aborted or preempted.
  auto moveArm(sim::Side side, const sim::JointPositions& goal, const MoveSettings& settings)
      -> std::string;

  /// Logs `why` and returns `aborted`.
  auto abort(std::string_view why) -> std::string;
  /// Services the preempt request and returns `preempted`.
  auto preempted() -> std::string;

 private:
  RobotContext& context_;
};

}  // namespace smachac::robot
