// BaxterBase: the start-up and the end of a generated Baxter program (the C++ form of the
// BaxterBase template, which extends the core Base):
//
//   int main(int argc, char** argv) {
//     auto robot = smachac::robot::setUpBaxter(argc, argv);   // takes the robot's flags out
//     if (!robot) return 2;
//     rt::StateMachine sm({.outcomes = {...}, .userdata = {...}});
//     sm.add("LOAD_TABLE_MODEL", std::make_unique<robot::LoadGazeboModelState>(*robot, ...), ...);
//     ...
//     return smachac::robot::runBaxter(sm, *robot, argc, argv);
//   }
//
// Robot flags (removed from argv, so that runMain sees only its own):
//   --snapshots=DIR          PNG snapshots at key moments (also SMACHAC_SNAPSHOTS=DIR)
//   --scene=PATH             another MJCF scene holding sim/models/baxter.xml
//   --start-pose=none|neutral|untuck   where both arms go before the machine starts
//   --no-report              no scene report at the end
//   --robot-quiet            no robot log lines on stderr
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "smachac/robot/report.h"
#include "smachac/robot/robot_context.h"
#include "smachac/runtime/state.h"

namespace smachac::robot {

namespace rt = smachac::runtime;

/// Applies and removes the robot flags in argv (argc shrinks). Returns an error message for a
/// bad value, or nothing.
std::optional<std::string> takeRobotFlags(int& argc, char** argv, RobotOptions& options);

/// Options from the environment and the flags, then RobotContext::create. Prints the problem
/// to stderr and returns nullptr on failure.
std::unique_ptr<RobotContext> setUpBaxter(int& argc, char** argv);

/// Steps options().settle_seconds of simulated time (the blocks come to rest), takes a
/// last snapshot, and returns the scene report.
SceneReport finishBaxter(RobotContext& context);

/// runMain(root, argc, argv), then finishBaxter and, unless disabled, the printed report.
/// Returns runMain's exit code.
int runBaxter(rt::State& root, RobotContext& context, int argc, char** argv);

}  // namespace smachac::robot
