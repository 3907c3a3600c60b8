// Gripper: mirrored finger commands, settling, jaw gap and grasp detection from contacts.
#include "smachac/sim/gripper.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "robot_names.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

constexpr double kSettledSpeed = 2e-3;  // m/s: a finger slower than this has stopped
constexpr int kSettledSteps = 25;       // consecutive slow steps that count as settled

// The bodies a pad geom touches.
std::set<int> touchedBodies(const mjModel* model, const mjData* data, int pad) {
  std::set<int> bodies;
  for (int i = 0; i < data->ncon; ++i) {
    const mjContact& contact = data->contact[i];
    if (contact.geom1 == pad) bodies.insert(model->geom_bodyid[contact.geom2]);
    if (contact.geom2 == pad) bodies.insert(model->geom_bodyid[contact.geom1]);
  }
  return bodies;
}

bool isFreeBody(const mjModel* model, int body) {
  return model->body_jntnum[body] == 1 && model->jnt_type[model->body_jntadr[body]] == mjJNT_FREE;
}

}  // namespace

Gripper::Gripper(World& world, Side side) : world_(world), side_(side) {
  const mjModel* model = world_.model();
  for (int f = 0; f < 2; ++f) {
    const int joint = detail::objectId(model, mjOBJ_JOINT, detail::fingerJointName(side, f));
    finger_qpos_[f] = model->jnt_qposadr[joint];
    finger_dof_[f] = model->jnt_dofadr[joint];
    actuator_[f] = detail::objectId(model, mjOBJ_ACTUATOR, detail::fingerActuatorName(side, f));
    pad_[f] = detail::objectId(model, mjOBJ_GEOM, detail::padGeomName(side, f));
    // Open is the end of the range away from zero (l: upper, r: lower); closed is zero.
    const double* range = model->jnt_range + 2 * joint;
    open_command_[f] = std::abs(range[1]) > std::abs(range[0]) ? range[1] : range[0];
  }
}

void Gripper::commandOpen() { commandOpening(1.0); }

void Gripper::commandClose() { commandOpening(0.0); }

void Gripper::commandOpening(double fraction) {
  auto guard = world_.lock();
  opening_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : opening_;
}

void Gripper::applyControl() {
  mjData* data = world_.data();
  for (int f = 0; f < 2; ++f) data->ctrl[actuator_[f]] = opening_ * open_command_[f];
}

double Gripper::opening() const {
  auto guard = world_.lock();
  const mjData* data = world_.data();
  double sum = 0.0;
  for (int f = 0; f < 2; ++f) sum += data->qpos[finger_qpos_[f]] / open_command_[f];
  return std::clamp(sum / 2.0, 0.0, 1.0);
}

double Gripper::fingerForce() const {
  auto guard = world_.lock();
  const mjData* data = world_.data();
  return (std::abs(data->actuator_force[actuator_[0]]) +
          std::abs(data->actuator_force[actuator_[1]])) /
         2.0;
}

bool Gripper::moving() const {
  auto guard = world_.lock();
  return fingerSpeed() >= kSettledSpeed;
}

double Gripper::fingerSpeed() const {
  const mjData* data = world_.data();
  return std::max(std::abs(data->qvel[finger_dof_[0]]), std::abs(data->qvel[finger_dof_[1]]));
}

bool Gripper::waitSettled(const GripperOptions& options) {
  int slow_steps = 0;
  return world_.stepUntil(
      [&] {
        slow_steps = fingerSpeed() < kSettledSpeed ? slow_steps + 1 : 0;
        return slow_steps > kSettledSteps;
      },
      options.timeout);
}

GripperResult Gripper::open(const GripperOptions& options) {
  commandOpen();
  return resultAfter(waitSettled(options), false);
}

GripperResult Gripper::close(const GripperOptions& options) {
  commandClose();
  return resultAfter(waitSettled(options), true);
}

GripperResult Gripper::resultAfter(bool settled, bool closing) const {
  GripperResult result;
  result.gap = gap();
  if (!settled) return result;
  if (!closing) {
    result.status = GripperStatus::Opened;
    return result;
  }
  const auto held = heldBody();
  result.status = held ? GripperStatus::Grasped : GripperStatus::ClosedEmpty;
  result.held_body = held.value_or("");
  return result;
}

double Gripper::gap() const {
  auto guard = world_.lock();
  const mjModel* model = world_.model();
  const mjData* data = world_.data();
  const double* l = data->geom_xpos + 3 * pad_[0];
  const double* r = data->geom_xpos + 3 * pad_[1];
  const double* frame = data->geom_xmat + 9 * pad_[0];  // columns are the pad's axes
  double across = 0.0;
  for (int k = 0; k < 3; ++k) across += (l[k] - r[k]) * frame[3 * k + 1];
  return std::abs(across) - model->geom_size[3 * pad_[0] + 1] - model->geom_size[3 * pad_[1] + 1];
}

std::optional<std::string> Gripper::heldBody() const {
  auto guard = world_.lock();
  const mjModel* model = world_.model();
  const std::set<int> left = touchedBodies(model, world_.data(), pad_[0]);
  for (int body : touchedBodies(model, world_.data(), pad_[1])) {
    if (left.count(body) > 0 && isFreeBody(model, body)) {
      return std::string(mj_id2name(model, mjOBJ_BODY, body));
    }
  }
  return std::nullopt;
}

}  // namespace smachac::sim
