// BaxterBase: robot flags, world start-up, and the end-of-run report.
#include "smachac/robot/baxter_base.h"

#include <cstdlib>
#include <iostream>
#include <string_view>

#include "smachac/runtime/run.h"

namespace smachac::robot {
namespace {

std::optional<StartPose> parseStartPose(std::string_view name) {
  if (name == "none") return StartPose::None;
  if (name == "neutral") return StartPose::Neutral;
  if (name == "untuck") return StartPose::Untuck;
  return std::nullopt;
}

// Applies one flag; false when it is not a robot flag. `error` is set for a bad value.
bool applyFlag(std::string_view arg, RobotOptions& options, std::optional<std::string>& error) {
  if (arg.starts_with("--snapshots=")) {
    options.snapshot_dir = arg.substr(12);
  } else if (arg.starts_with("--scene=")) {
    options.scene = arg.substr(8);
  } else if (arg.starts_with("--start-pose=")) {
    const auto pose = parseStartPose(arg.substr(13));
    if (!pose) error = "unknown start pose `" + std::string(arg.substr(13)) + "`";
    options.start_pose = pose.value_or(StartPose::None);
  } else if (arg == "--no-report") {
    options.report = false;
  } else if (arg == "--robot-quiet") {
    options.quiet = true;
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::optional<std::string> takeRobotFlags(int& argc, char** argv, RobotOptions& options) {
  std::optional<std::string> error;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (!applyFlag(argv[i], options, error)) argv[kept++] = argv[i];
  }
  argc = kept;
  argv[argc] = nullptr;
  return error;
}

std::unique_ptr<RobotContext> setUpBaxter(int& argc, char** argv) {
  RobotOptions options;
  if (const char* dir = std::getenv("SMACHAC_SNAPSHOTS")) options.snapshot_dir = dir;
  if (auto error = takeRobotFlags(argc, argv, options)) {
    std::cerr << "error: " << *error << "\n";
    return nullptr;
  }
  std::string error;
  auto context = RobotContext::create(std::move(options), error);
  if (!context) std::cerr << "error: cannot start the simulated Baxter: " << error << "\n";
  return context;
}

SceneReport finishBaxter(RobotContext& context) {
  context.world().stepFor(context.options().settle_seconds);
  context.snapshot("final");
  return sceneReport(context.world());
}

int runBaxter(rt::State& root, RobotContext& context, int argc, char** argv) {
  root.setThreadObserver(&context);  // simulated time waits for late-starting arms
  const int code = rt::runMain(root, argc, argv);
  if (code == 2) return code;
  const SceneReport report = finishBaxter(context);
  if (context.options().report) printReport(std::cout, report);
  return code;
}

}  // namespace smachac::robot
