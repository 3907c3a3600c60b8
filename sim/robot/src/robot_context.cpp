// RobotContext: the shared world, the log and the snapshots.
#include "smachac/robot/robot_context.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "smachac/sim/snapshot.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::robot {
namespace {

constexpr double kStartMoveTimeout = 20.0;  // simulated seconds

sim::JointPositions startJoints(StartPose pose, sim::Side side) {
  return pose == StartPose::Neutral ? sim::neutralPose(side) : sim::untuckPose(side);
}

// Moves both arms at once; false when they do not get there in time.
bool moveBothArms(sim::World& world, StartPose pose, const sim::MoveOptions& move) {
  sim::Limb& left = world.limb(sim::Side::Left);
  sim::Limb& right = world.limb(sim::Side::Right);
  if (!left.startMove(startJoints(pose, sim::Side::Left), move) ||
      !right.startMove(startJoints(pose, sim::Side::Right), move)) {
    return false;
  }
  return world.stepUntil([&] { return left.moveDone() && right.moveDone(); }, kStartMoveTimeout);
}

std::string fileLabel(std::string_view label) {
  std::string name(label.empty() ? "root" : label);
  for (char& c : name) {
    if (c == '/' || c == ' ') c = '.';
  }
  return name;
}

}  // namespace

RobotContext::RobotContext(std::unique_ptr<sim::World> world, RobotOptions options)
    : world_(std::move(world)), options_(std::move(options)) {}

RobotContext::~RobotContext() = default;

std::unique_ptr<RobotContext> RobotContext::create(RobotOptions options, std::string& error) {
  sim::LoadResult loaded =
      options.scene.empty() ? sim::World::loadDefault() : sim::World::load(options.scene);
  if (!loaded.world) {
    error = loaded.error;
    return nullptr;
  }
  auto context = std::make_unique<RobotContext>(std::move(loaded.world), std::move(options));
  const StartPose start = context->options().start_pose;
  if (start != StartPose::None && !moveBothArms(context->world(), start, context->options().move)) {
    error = "the arms did not reach their start pose";
    return nullptr;
  }
  return context;
}

bool RobotContext::stepUntil(const std::function<bool()>& done, double timeout) {
  const double deadline = world_->time() + timeout;
  for (;;) {
    {
      auto guard = world_->lock();
      if (done()) return true;
      if (world_->time() >= deadline) return false;
    }
    std::unique_lock lock(step_mutex_);
    const uint64_t seen = generation_;
    ++waiting_;
    const auto everyone = [&] { return waiting_ >= std::max(executing_, threads_); };
    if (!step_cv_.wait_for(lock, kLateThreadGrace,
                           [&] { return generation_ != seen || everyone(); })) {
      // Some thread of the machine is busy outside robot states: go on without it.
      step_cv_.wait(lock, [&] { return generation_ != seen || waiting_ >= executing_; });
    }
    if (generation_ != seen) continue;  // another thread stepped for everyone
    world_->step(1);
    ++generation_;
    waiting_ = 0;
    lock.unlock();
    step_cv_.notify_all();
  }
}

void RobotContext::beginExecution() {
  std::lock_guard lock(step_mutex_);
  ++executing_;
}

void RobotContext::endExecution() {
  {
    std::lock_guard lock(step_mutex_);
    --executing_;
  }
  step_cv_.notify_all();  // the threads still waiting may now be all there is
}

void RobotContext::split(std::size_t children) {
  std::lock_guard lock(step_mutex_);
  threads_ += static_cast<int>(children) - 1;
}

void RobotContext::returned() {
  {
    std::lock_guard lock(step_mutex_);
    --threads_;
  }
  step_cv_.notify_all();
}

void RobotContext::joined() {
  std::lock_guard lock(step_mutex_);
  ++threads_;
}

void RobotContext::log(std::string_view path, std::string_view message) {
  std::string line = "[robot] " + std::string(path.empty() ? "root" : path) + ": ";
  line += message;
  std::lock_guard guard(log_mutex_);
  messages_.push_back(line);
  if (!options_.quiet) (options_.log ? *options_.log : std::cerr) << line << "\n";
}

std::vector<std::string> RobotContext::messages() const {
  std::lock_guard guard(log_mutex_);
  return messages_;
}

std::string RobotContext::snapshot(std::string_view label) {
  if (options_.snapshot_dir.empty()) return "";
  std::unique_lock guard(snapshot_mutex_);
  std::ostringstream path;
  path << options_.snapshot_dir << "/" << std::setw(3) << std::setfill('0') << snapshots_.size()
       << "_" << fileLabel(label) << ".png";
  std::error_code ignored;
  std::filesystem::create_directories(options_.snapshot_dir, ignored);
  if (!snapshotter_) snapshotter_ = std::make_unique<sim::Snapshotter>(*world_);
  const sim::SnapshotResult result = snapshotter_->writePng(path.str());
  if (!result.ok) {
    guard.unlock();
    log(label, "snapshot failed: " + result.error);
    return "";
  }
  snapshots_.push_back(path.str());
  return path.str();
}

std::vector<std::string> RobotContext::snapshots() const {
  std::lock_guard guard(snapshot_mutex_);
  return snapshots_;
}

}  // namespace smachac::robot
