// The C interface of sim_bridge.h over World, Limb, Gripper, Ik, bodies and the scene report.
#include "sim_bridge.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>

#include "smachac/robot/report.h"
#include "smachac/sim/bodies.h"
#include "smachac/sim/gripper.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/snapshot.h"
#include "smachac/sim/world.h"

namespace sim = smachac::sim;

struct SmachacSimWorld {
  std::unique_ptr<sim::World> world;
  std::unique_ptr<sim::Ik> ik;
  std::unique_ptr<sim::Snapshotter> snapshotter;
  std::array<std::array<std::string, sim::kArmJointCount>, 2> joint_names;
  std::array<std::array<int, sim::kArmJointCount>, 2> actuators;  // a joint's servo, or -1
  std::array<std::array<int, sim::kArmJointCount>, 2> dofs;       // a joint's dof, or -1
};

namespace {

constexpr double kMaxFingerForce = 20.0;  // N, the finger servos' limit

sim::Side sideOf(int side) { return side == 1 ? sim::Side::Right : sim::Side::Left; }

// Writes `text` into a caller's buffer (NUL-terminated, cut to fit); returns its length.
int copyOut(const std::string& text, char* buffer, int size) {
  if (buffer != nullptr && size > 0) {
    const size_t length = std::min(text.size(), static_cast<size_t>(size - 1));
    std::memcpy(buffer, text.data(), length);
    buffer[length] = '\0';
  }
  return static_cast<int>(text.size());
}

sim::Pose poseFrom(const double values[7]) {
  return {{values[0], values[1], values[2]}, {values[6], values[3], values[4], values[5]}};
}

void poseTo(const sim::Pose& pose, double values[7]) {
  const double out[7] = {pose.position.x,    pose.position.y,    pose.position.z,
                         pose.orientation.x, pose.orientation.y, pose.orientation.z,
                         pose.orientation.w};
  std::copy(out, out + 7, values);
}

void arrayTo(const sim::JointPositions& joints, double values[7]) {
  std::copy(joints.begin(), joints.end(), values);
}

// The TCP's linear and angular velocity in the world frame, from the site Jacobian.
std::array<double, 6> endpointTwist(const sim::World& world, sim::Side side) {
  auto guard = world.lock();
  const mjModel* model = world.model();
  const mjData* data = world.data();
  const std::string site = std::string(sim::sideName(side)) + "_gripper";
  const int id = mj_name2id(model, mjOBJ_SITE, site.c_str());
  std::array<double, 6> twist{};
  if (id < 0) return twist;
  std::unique_ptr<mjtNum[]> jacobian(new mjtNum[6 * model->nv]);
  mj_jacSite(model, data, jacobian.get(), jacobian.get() + 3 * model->nv, id);
  mju_mulMatVec(twist.data(), jacobian.get(), data->qvel, 6, model->nv);
  return twist;
}

}  // namespace

extern "C" {

SmachacSimWorld* smachac_sim_open(const char* scene_path, char* error, int error_size) {
  const bool use_default = scene_path == nullptr || *scene_path == '\0';
  sim::LoadResult loaded = use_default ? sim::World::loadDefault() : sim::World::load(scene_path);
  if (!loaded.world) {
    copyOut(loaded.error, error, error_size);
    return nullptr;
  }
  auto handle = std::make_unique<SmachacSimWorld>();
  handle->world = std::move(loaded.world);
  handle->ik = std::make_unique<sim::Ik>(*handle->world);
  const mjModel* model = handle->world->model();
  for (size_t side = 0; side < 2; ++side) {
    handle->joint_names[side] = handle->world->limb(sideOf(static_cast<int>(side))).jointNames();
    for (size_t i = 0; i < sim::kArmJointCount; ++i) {
      const char* name = handle->joint_names[side][i].c_str();
      handle->actuators[side][i] = mj_name2id(model, mjOBJ_ACTUATOR, name);
      const int joint = mj_name2id(model, mjOBJ_JOINT, name);
      handle->dofs[side][i] = joint < 0 ? -1 : model->jnt_dofadr[joint];
    }
  }
  return handle.release();
}

void smachac_sim_close(SmachacSimWorld* world) { delete world; }

double smachac_sim_step(SmachacSimWorld* world, int count) {
  world->world->step(std::max(count, 0));
  return world->world->time();
}

double smachac_sim_time(const SmachacSimWorld* world) { return world->world->time(); }

double smachac_sim_timestep(const SmachacSimWorld* world) { return world->world->timestep(); }

void smachac_sim_joint_names(const SmachacSimWorld* world, int side, const char* names[7]) {
  const auto& side_names = world->joint_names[side == 1 ? 1 : 0];
  for (size_t i = 0; i < side_names.size(); ++i) names[i] = side_names[i].c_str();
}

void smachac_sim_joint_state(const SmachacSimWorld* world, int side, double position[7],
                             double velocity[7], double effort[7]) {
  const sim::World& w = *world->world;
  const sim::Limb& limb = w.limb(sideOf(side));
  auto guard = w.lock();
  arrayTo(limb.jointPositions(), position);
  arrayTo(limb.jointVelocities(), velocity);
  // The servo's force plus the gravity compensation applied with it: the joint's torque.
  const auto& actuators = world->actuators[side == 1 ? 1 : 0];
  const auto& dofs = world->dofs[side == 1 ? 1 : 0];
  for (size_t i = 0; i < actuators.size(); ++i) {
    effort[i] = (actuators[i] < 0 ? 0.0 : w.data()->actuator_force[actuators[i]]) +
                (dofs[i] < 0 ? 0.0 : w.data()->qfrc_applied[dofs[i]]);
  }
}

int smachac_sim_command_positions(SmachacSimWorld* world, int side, const double goal[7],
                                  double speed) {
  sim::JointPositions joints{};
  std::copy(goal, goal + sim::kArmJointCount, joints.begin());
  return world->world->limb(sideOf(side)).commandPositions(joints, speed) ? 1 : 0;
}

void smachac_sim_endpoint(const SmachacSimWorld* world, int side, double pose[7], double twist[6]) {
  const sim::World& w = *world->world;
  poseTo(w.limb(sideOf(side)).endpointPose(sim::Frame::Base), pose);
  const auto velocity = endpointTwist(w, sideOf(side));
  std::copy(velocity.begin(), velocity.end(), twist);  // the base frame is not rotated
}

int smachac_sim_solve_ik(SmachacSimWorld* world, int side, const double pose[7], double joints[7]) {
  const sim::IkResult result = world->ik->solve(sideOf(side), poseFrom(pose), sim::Frame::Base);
  arrayTo(result.joints, joints);
  return result.ok() ? 1 : 0;
}

void smachac_sim_gripper_command(SmachacSimWorld* world, int side, double percent) {
  world->world->gripper(sideOf(side)).commandOpening(percent / 100.0);
}

void smachac_sim_gripper_state(const SmachacSimWorld* world, int side, double* percent, int* moving,
                               int* gripping, double* force) {
  const sim::Gripper& gripper = world->world->gripper(sideOf(side));
  *percent = 100.0 * gripper.opening();
  *moving = gripper.moving() ? 1 : 0;
  *gripping = !*moving && gripper.heldBody().has_value() ? 1 : 0;
  *force = 100.0 * std::min(gripper.fingerForce() / kMaxFingerForce, 1.0);
}

int smachac_sim_place_body(SmachacSimWorld* world, const char* name, const double pose[7],
                           int frame) {
  const sim::Frame where = frame == 1 ? sim::Frame::World : sim::Frame::Base;
  return static_cast<int>(sim::placeBody(*world->world, name, poseFrom(pose), where));
}

int smachac_sim_body_pose(const SmachacSimWorld* world, const char* name, double pose[7]) {
  const auto found = sim::bodyPose(*world->world, name, sim::Frame::Base);
  if (!found) return 0;
  poseTo(*found, pose);
  return 1;
}

int smachac_sim_report(const SmachacSimWorld* world, char* text, int size) {
  std::ostringstream out;
  smachac::robot::printReport(out, smachac::robot::sceneReport(*world->world));
  return copyOut(out.str(), text, size);
}

int smachac_sim_snapshot(SmachacSimWorld* world, const char* path, char* error, int error_size) {
  if (!world->snapshotter) world->snapshotter = std::make_unique<sim::Snapshotter>(*world->world);
  const sim::SnapshotResult result = world->snapshotter->writePng(path);
  if (!result.ok) copyOut(result.error, error, error_size);
  return result.ok ? 1 : 0;
}

}  // extern "C"
