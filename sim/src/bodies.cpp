// placeBody / bodyPose: moving free and mocap bodies, reading body poses.
#include "smachac/sim/bodies.h"

#include <mujoco/mujoco.h>

#include <string>

#include "pose_math.h"
#include "robot_names.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

// The address of a body's free joint in qpos and qvel, or {-1, -1}.
std::pair<int, int> freeJointAddress(const mjModel* model, int body) {
  if (model->body_jntnum[body] != 1) return {-1, -1};
  const int joint = model->body_jntadr[body];
  if (model->jnt_type[joint] != mjJNT_FREE) return {-1, -1};
  return {model->jnt_qposadr[joint], model->jnt_dofadr[joint]};
}

void writeFree(mjData* data, std::pair<int, int> address, const Pose& pose) {
  double* qpos = data->qpos + address.first;
  const double values[7] = {pose.position.x,    pose.position.y,    pose.position.z,
                            pose.orientation.w, pose.orientation.x, pose.orientation.y,
                            pose.orientation.z};
  for (int i = 0; i < 7; ++i) qpos[i] = values[i];
  for (int i = 0; i < 6; ++i) data->qvel[address.second + i] = 0.0;
}

void writeMocap(mjData* data, int mocap, const Pose& pose) {
  const double position[3] = {pose.position.x, pose.position.y, pose.position.z};
  const double quaternion[4] = {pose.orientation.w, pose.orientation.x, pose.orientation.y,
                                pose.orientation.z};
  for (int i = 0; i < 3; ++i) data->mocap_pos[3 * mocap + i] = position[i];
  for (int i = 0; i < 4; ++i) data->mocap_quat[4 * mocap + i] = quaternion[i];
}

}  // namespace

PlaceStatus placeBody(World& world, std::string_view name, const Pose& pose, Frame frame) {
  const mjModel* model = world.model();
  const int body = detail::objectId(model, mjOBJ_BODY, std::string(name));
  if (body < 0) return PlaceStatus::UnknownBody;
  if (!detail::isValidPose(pose)) return PlaceStatus::InvalidPose;
  const Pose target = world.toWorld(detail::normalized(pose), frame);
  const auto address = freeJointAddress(model, body);
  const int mocap = model->body_mocapid[body];
  if (address.first < 0 && mocap < 0) return PlaceStatus::NotMovable;
  auto guard = world.lock();
  if (address.first >= 0) writeFree(world.data(), address, target);
  if (mocap >= 0) writeMocap(world.data(), mocap, target);
  mj_forward(model, world.data());
  return PlaceStatus::Placed;
}

std::optional<Pose> bodyPose(const World& world, std::string_view name, Frame frame) {
  const mjModel* model = world.model();
  const int body = detail::objectId(model, mjOBJ_BODY, std::string(name));
  if (body < 0) return std::nullopt;
  auto guard = world.lock();
  const mjData* data = world.data();
  return world.fromWorld(detail::poseFromMujoco(data->xpos + 3 * body, data->xmat + 9 * body),
                         frame);
}

}  // namespace smachac::sim
