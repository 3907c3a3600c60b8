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

auto inputs(const GripperInterfaceArgs& args) -> rt::Keys {
  rt::Keys keys;
  if (args.limb.empty()) keys.push_back("limb");
  if (args.command.empty()) keys.push_back("command");
  return keys;
}

auto isClose(const std::string& command) -> bool {
  if (command == "close") return true;
  if (command == "open") return false;
  throw FormatError("a gripper command must be `open` or `close`, not `" + command + "`");
}

}  // namespace

GripperInterfaceState::GripperInterfaceState(RobotContext& context, GripperInterfaceArgs args)
    : RobotState(context, inputs(args)), args_(std::move(args)) {}

auto GripperInterfaceState::run(rt::UserData& userdata) -> std::string {
  const sim::Side side = limbOf(args_.limb, userdata);
  const bool close =
      isClose(args_.command.empty() ? userdata.get<std::string>("command") : args_.command);
  const auto result = actuate(world().gripper(side), close);
  if (!result) return preempted();
  return judge(*result, close);
}

auto GripperInterfaceState::actuate(sim::Gripper& gripper, bool close)
    -> std::optional<sim::GripperResult> {
  close ? gripper.commandClose() : gripper.commandOpen();
  double gap = gripper.gap();
  double time = world().time();
  double slowSince = time;
  const bool settled = context().stepUntil(
      [&] {
        if (preemptRequested()) return true;
        const double now = world().time();
        if (now <= time) return false;
        const double nowGap = gripper.gap();
        if (std::abs(nowGap - gap) >= kSettledRate * (now - time)) slowSince = now;
        gap = nowGap;
        time = now;
        return now - slowSince >= kSettledTime;
      },
      args_.timeout);
  if (preemptRequested()) return std::nullopt;
  return outcome(gripper, settled, close);
}

auto GripperInterfaceState::outcome(const sim::Gripper& gripper, bool settled, bool close)
    -> sim::GripperResult {
  sim::GripperResult result;
  result.gap = gripper.gap();
  if (!settled) return result;
  const auto held = gripper.heldBody();
  if (close && held) result.heldBody = *held;
  result.status = !close ? sim::GripperStatus::kOpened
                  : held ? sim::GripperStatus::kGrasped
                         : sim::GripperStatus::kClosedEmpty;
  return result;
}

auto GripperInterfaceState::judge(const sim::GripperResult& result, bool close) -> std::string {
  if (result.status == sim::GripperStatus::kTimeout) return abort("the fingers did not settle");
  if (close && args_.expect_grasp && result.status != sim::GripperStatus::kGrasped) {
    return abort("the gripper closed on nothing");
  }
  context().snapshot(path());
  return std::string(kSucceeded);
}

}  // namespace smachac::robot
