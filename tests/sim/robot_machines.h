// The paper's three Baxter experiments assembled with the runtime API exactly as the C++ that
// `smachac -target=cpp` generates from examples/baxter/*.yml assembles them: one StateMachine
// or Concurrence per container, one robot state per leaf, the scripts' names, transitions,
// remappings and userdata. A sub-script included several times is built by one function
// (generated code repeats it at each inclusion).
#pragma once

#include <memory>

#include "smachac/robot/robot.h"
#include "smachac/runtime/runtime.h"

namespace smachac::robot::test {

namespace rt = smachac::runtime;

/// A context over a freshly loaded default scene; its log is kept but not printed.
std::unique_ptr<RobotContext> makeRobot(RobotOptions options = {});

/// examples/baxter/pick_and_place.yml
std::unique_ptr<rt::StateMachine> buildPickAndPlace(RobotContext& robot);
/// examples/baxter/stacking.yml
std::unique_ptr<rt::StateMachine> buildStacking(RobotContext& robot);
/// examples/baxter/dual_arm_stacking.yml
std::unique_ptr<rt::StateMachine> buildDualArmStacking(RobotContext& robot);

/// Puts block <n> of a stacking or dual-arm machine at (x, y) on the table: the userdata its
/// LOAD_BLOCK_MODEL_<n> state loads it from, and the pick pose that follows it.
void setBlockPlacement(rt::StateMachine& sm, int n, double x, double y);

/// examples/baxter/sub/pick_block.yml included in `parent` as `label`.
void addPickBlock(rt::StateMachine& parent, RobotContext& robot, const std::string& label,
                  rt::Transitions transitions, rt::Remapping remapping);
/// examples/baxter/sub/place_block.yml included in `parent` as `label`.
void addPlaceBlock(rt::StateMachine& parent, RobotContext& robot, const std::string& label,
                   rt::Transitions transitions, rt::Remapping remapping);

}  // namespace smachac::robot::test
