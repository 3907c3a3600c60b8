// World: loading, stepping with servo commands and gravity compensation, time, reset,
// warnings, real-time factor and frame conversion.
#include "smachac/sim/world.h"

#include <mujoco/mujoco.h>

#include <array>
#include <chrono>
#include <cmath>

#include "pose_math.h"
#include "robot_names.h"
#include "smachac/sim/gripper.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/model_path.h"

namespace smachac::sim {
namespace detail {
void installMujocoMessageHook();
}  // namespace detail

namespace {

constexpr std::array<const char*, mjNWARNING> kWarningNames = {
    "mjWARN_INERTIA", "mjWARN_CONTACTFULL", "mjWARN_CNSTRFULL", "mjWARN_VGEOMFULL",
    "mjWARN_BADQPOS", "mjWARN_BADQVEL",     "mjWARN_BADQACC",   "mjWARN_BADCTRL"};

auto sideIndex(Side side) -> int { return side == Side::kLeft ? 0 : 1; }

// Every degree of freedom that does not belong to a free joint: the robot's.
auto robotDofs(const mjModel* model) -> std::vector<int> {
  std::vector<int> dofs;
  for (int j = 0; j < model->njnt; ++j) {
    if (model->jnt_type[j] == mjJNT_FREE || model->jnt_type[j] == mjJNT_BALL) continue;
    dofs.push_back(model->jnt_dofadr[j]);
  }
  return dofs;
}

auto loadModel(const std::string& path, std::string& error) -> mjModel* {
  std::array<char, 1024> message{};
  mjModel* model = mj_loadXML(path.c_str(), nullptr, message.data(), message.size());
  if (model == nullptr) error = "cannot load `" + path + "`: " + message.data();
  return model;
}

}  // namespace

auto World::load(const std::string& scenePath) -> LoadResult {
  detail::installMujocoMessageHook();
  LoadResult result;
  mjModel* model = loadModel(scenePath, result.error);
  if (model == nullptr) return result;
  result.error = detail::checkRobotNames(model);
  if (!result.error.empty()) {
    result.error = "`" + scenePath + "`: " + result.error;
    mj_deleteModel(model);
    return result;
  }
  result.world.reset(new World(model, mj_makeData(model)));
  return result;
}

auto World::loadDefault() -> LoadResult { return load(defaultScenePath()); }

World::World(mjModel* model, mjData* data) : model_(model), data_(data) {
  for (Side side : {Side::kLeft, Side::kRight}) {
    limbs_[sideIndex(side)] = std::make_unique<Limb>(*this, side);
    grippers_[sideIndex(side)] = std::make_unique<Gripper>(*this, side);
  }
  robotDofs_ = robotDofs(model_);
  const int base = detail::objectId(model_, mjOBJ_BODY, detail::kBaseBody);
  mj_forward(model_, data_);
  basePose_ = detail::poseFromMujoco(data_->xpos + 3 * base, data_->xmat + 9 * base);
  reset();
}

World::~World() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

void World::reset() {
  auto guard = lock();
  mj_resetData(model_, data_);
  mj_forward(model_, data_);
  for (auto& limb : limbs_) limb->holdCurrent();
  for (auto& gripper : grippers_) gripper->commandOpen();
  resetTiming();
}

void World::step(int count) {
  auto guard = lock();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < count; ++i) stepLocked();
  wallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void World::stepFor(double seconds) { step(static_cast<int>(std::lround(seconds / timestep()))); }

auto World::stepUntil(const std::function<bool()>& done, double timeout) -> bool {
  const double deadline = time() + timeout;
  for (;;) {
    auto guard = lock();
    if (done()) return true;
    if (data_->time >= deadline) return false;
    step(1);
  }
}

void World::stepLocked() {
  mj_step1(model_, data_);
  for (auto& limb : limbs_) limb->applyControl(data_->time);
  for (auto& gripper : grippers_) gripper->applyControl();
  applyGravityCompensation();
  mj_step2(model_, data_);
  simSeconds_ += model_->opt.timestep;
}

void World::applyGravityCompensation() {
  for (int dof : robotDofs_) data_->qfrc_applied[dof] = data_->qfrc_bias[dof];
}

auto World::time() const -> double {
  auto guard = lock();
  return data_->time;
}

auto World::timestep() const -> double { return model_->opt.timestep; }

auto World::limb(Side side) -> Limb& { return *limbs_[sideIndex(side)]; }
auto World::limb(Side side) const -> const Limb& { return *limbs_[sideIndex(side)]; }
auto World::gripper(Side side) -> Gripper& { return *grippers_[sideIndex(side)]; }
auto World::gripper(Side side) const -> const Gripper& { return *grippers_[sideIndex(side)]; }

auto World::warnings() const -> std::vector<WarningCount> {
  auto guard = lock();
  std::vector<WarningCount> raised;
  for (int i = 0; i < mjNWARNING; ++i) {
    if (data_->warning[i].number > 0)
      raised.push_back({kWarningNames[i], data_->warning[i].number});
  }
  return raised;
}

auto World::hasWarnings() const -> bool { return !warnings().empty(); }

auto World::realTimeFactor() const -> double {
  auto guard = lock();
  return wallSeconds_ > 0.0 ? simSeconds_ / wallSeconds_ : 0.0;
}

void World::resetTiming() {
  auto guard = lock();
  wallSeconds_ = 0.0;
  simSeconds_ = 0.0;
}

auto World::toWorld(const Pose& pose, Frame frame) const -> Pose {
  return frame == Frame::kWorld ? pose : detail::compose(basePose_, pose);
}

auto World::fromWorld(const Pose& pose, Frame frame) const -> Pose {
  return frame == Frame::kWorld ? pose : detail::compose(detail::inverse(basePose_), pose);
}

auto World::model() const -> const mjModel* { return model_; }
auto World::data() -> mjData* { return data_; }
auto World::data() const -> const mjData* { return data_; }

auto World::lock() const -> std::unique_lock<std::recursive_mutex> {
  return std::unique_lock(mutex_);
}

}  // namespace smachac::sim
