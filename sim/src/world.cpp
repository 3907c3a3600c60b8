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

int sideIndex(Side side) { return side == Side::Left ? 0 : 1; }

// Every degree of freedom that does not belong to a free joint: the robot's.
std::vector<int> robotDofs(const mjModel* model) {
  std::vector<int> dofs;
  for (int j = 0; j < model->njnt; ++j) {
    if (model->jnt_type[j] == mjJNT_FREE || model->jnt_type[j] == mjJNT_BALL) continue;
    dofs.push_back(model->jnt_dofadr[j]);
  }
  return dofs;
}

mjModel* loadModel(const std::string& path, std::string& error) {
  std::array<char, 1024> message{};
  mjModel* model = mj_loadXML(path.c_str(), nullptr, message.data(), message.size());
  if (model == nullptr) error = "cannot load `" + path + "`: " + message.data();
  return model;
}

}  // namespace

LoadResult World::load(const std::string& scene_path) {
  detail::installMujocoMessageHook();
  LoadResult result;
  mjModel* model = loadModel(scene_path, result.error);
  if (model == nullptr) return result;
  result.error = detail::checkRobotNames(model);
  if (!result.error.empty()) {
    result.error = "`" + scene_path + "`: " + result.error;
    mj_deleteModel(model);
    return result;
  }
  result.world.reset(new World(model, mj_makeData(model)));
  return result;
}

LoadResult World::loadDefault() { return load(defaultScenePath()); }

World::World(mjModel* model, mjData* data) : model_(model), data_(data) {
  for (Side side : {Side::Left, Side::Right}) {
    limbs_[sideIndex(side)] = std::make_unique<Limb>(*this, side);
    grippers_[sideIndex(side)] = std::make_unique<Gripper>(*this, side);
  }
  robot_dofs_ = robotDofs(model_);
  const int base = detail::objectId(model_, mjOBJ_BODY, detail::kBaseBody);
  mj_forward(model_, data_);
  base_pose_ = detail::poseFromMujoco(data_->xpos + 3 * base, data_->xmat + 9 * base);
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
  wall_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void World::stepFor(double seconds) { step(static_cast<int>(std::lround(seconds / timestep()))); }

bool World::stepUntil(const std::function<bool()>& done, double timeout) {
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
  sim_seconds_ += model_->opt.timestep;
}

void World::applyGravityCompensation() {
  for (int dof : robot_dofs_) data_->qfrc_applied[dof] = data_->qfrc_bias[dof];
}

double World::time() const {
  auto guard = lock();
  return data_->time;
}

double World::timestep() const { return model_->opt.timestep; }

Limb& World::limb(Side side) { return *limbs_[sideIndex(side)]; }
const Limb& World::limb(Side side) const { return *limbs_[sideIndex(side)]; }
Gripper& World::gripper(Side side) { return *grippers_[sideIndex(side)]; }
const Gripper& World::gripper(Side side) const { return *grippers_[sideIndex(side)]; }

std::vector<WarningCount> World::warnings() const {
  auto guard = lock();
  std::vector<WarningCount> raised;
  for (int i = 0; i < mjNWARNING; ++i) {
    if (data_->warning[i].number > 0)
      raised.push_back({kWarningNames[i], data_->warning[i].number});
  }
  return raised;
}

bool World::hasWarnings() const { return !warnings().empty(); }

double World::realTimeFactor() const {
  auto guard = lock();
  return wall_seconds_ > 0.0 ? sim_seconds_ / wall_seconds_ : 0.0;
}

void World::resetTiming() {
  auto guard = lock();
  wall_seconds_ = 0.0;
  sim_seconds_ = 0.0;
}

Pose World::toWorld(const Pose& pose, Frame frame) const {
  return frame == Frame::World ? pose : detail::compose(base_pose_, pose);
}

Pose World::fromWorld(const Pose& pose, Frame frame) const {
  return frame == Frame::World ? pose : detail::compose(detail::inverse(base_pose_), pose);
}

const mjModel* World::model() const { return model_; }
mjData* World::data() { return data_; }
const mjData* World::data() const { return data_; }

std::unique_lock<std::recursive_mutex> World::lock() const { return std::unique_lock(mutex_); }

}  // namespace smachac::sim
