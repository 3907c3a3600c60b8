// GripperInterfaceState: open/close, settle (preemptible), grasp check.
#include "smachac/robot/gripper_interface_state.h"

#include <cmath>

#include "smachac/robot/formats.h"
#include "smachac/sim/gripper.h"

namespace smachac::robot {
namespace {

// The fingers have settled when the gap changes slower than this for kSettledTime.
constexpr double kSettledRate = 4e-3;  // m/s: both fingers slower than the sim's 2 mm/s
constexpr double kSettledTime = 0.05;  // simulated seconds (the sim's 25 steps)

rt::Keys inputs(const GripperInterfaceArgs& args) {
  rt::Keys keys;
  if (args.limb.empty()) keys.push_back("limb");
  if (args.command.empty()) keys.push_back("command");
  return keys;
}

bool isClose(const std::string& command) {
  if (command == "close") return true;
  if (command == "open") return false;
  throw FormatError("a gripper command must be `open` or `close`, not `" + command + "`");
}

}  // namespace

GripperInterfaceState::GripperInterfaceState(RobotContext& context, GripperInterfaceArgs args)
    : RobotState(context, inputs(args)), args_(std::move(args)) {}

std::string GripperInterfaceState::run(rt::UserData& userdata) {
  const sim::Side side = limbOf(args_.limb, userdata);
  const bool close =
      isClose(args_.command.empty() ? userdata.get<std::string>("command") : args_.command);
  const auto result = actuate(world().gripper(side), close);
  if (!result) return preempted();
  return judge(*result, close);
}

std::optional<sim::GripperResult> GripperInterfaceState::actuate(sim::Gripper& gripper,
                                                                 bool close) {
  close ? gripper.commandClose() : gripper.commandOpen();
  double gap = gripper.gap();
  double time = world().time();
  double slow_since = time;
  const bool settled = context().stepUntil(
      [&] {
        if (preemptRequested()) return true;
        const double now = world().time();
        if (now <= time) return false;
        const double now_gap = gripper.gap();
        if (std::abs(now_gap - gap) >= kSettledRate * (now - time)) slow_since = now;
        gap = now_gap;
        time = now;
        return now - slow_since >= kSettledTime;
      },
      args_.timeout);
  if (preemptRequested()) return std::nullopt;
  return outcome(gripper, settled, close);
}

sim::GripperResult GripperInterfaceState::outcome(const sim::Gripper& gripper, bool settled,
                                                  bool close) {
  sim::GripperResult result;
  result.gap = gripper.gap();
  if (!settled) return result;
  const auto held = gripper.heldBody();
  if (close && held) result.held_body = *held;
  result.status = !close ? sim::GripperStatus::Opened
                  : held ? sim::GripperStatus::Grasped
                         : sim::GripperStatus::ClosedEmpty;
  return result;
}

std::string GripperInterfaceState::judge(const sim::GripperResult& result, bool close) {
  if (result.status == sim::GripperStatus::Timeout) return abort("the fingers did not settle");
  if (close && args_.expect_grasp && result.status != sim::GripperStatus::Grasped) {
    return abort("the gripper closed on nothing");
  }
  context().snapshot(path());
  return std::string(kSucceeded);
}

}  // namespace smachac::robot
