// Pose conversions and rigid-body math on Eigen.
#include "pose_math.h"

#include <cmath>

namespace smachac::sim::detail {

auto toEigen(const Vec3& v) -> Eigen::Vector3d { return {v.x, v.y, v.z}; }

auto toEigen(const Quaternion& q) -> Eigen::Quaterniond { return {q.w, q.x, q.y, q.z}; }

auto toVec3(const Eigen::Vector3d& v) -> Vec3 { return {v.x(), v.y(), v.z()}; }

auto toQuaternion(const Eigen::Quaterniond& q) -> Quaternion {
  return {q.w(), q.x(), q.y(), q.z()};
}

auto poseFromMujoco(const double* position, const double* matrix) -> Pose {
  Eigen::Matrix3d rotation;
  rotation << matrix[0], matrix[1], matrix[2], matrix[3], matrix[4], matrix[5], matrix[6],
      matrix[7], matrix[8];
  Eigen::Quaterniond q(rotation);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return {{position[0], position[1], position[2]}, toQuaternion(q.normalized())};
}

auto compose(const Pose& a, const Pose& b) -> Pose {
  const Eigen::Quaterniond qa = toEigen(a.orientation);
  const Eigen::Vector3d p = toEigen(a.position) + qa * toEigen(b.position);
  return {toVec3(p), toQuaternion((qa * toEigen(b.orientation)).normalized())};
}

auto inverse(const Pose& pose) -> Pose {
  const Eigen::Quaterniond qi = toEigen(pose.orientation).conjugate();
  return {toVec3(-(qi * toEigen(pose.position))), toQuaternion(qi)};
}

auto isValidPose(const Pose& pose) -> bool {
  const double values[] = {pose.position.x,    pose.position.y,    pose.position.z,
                           pose.orientation.w, pose.orientation.x, pose.orientation.y,
                           pose.orientation.z};
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return toEigen(pose.orientation).norm() > 1e-6;
}

auto normalized(const Pose& pose) -> Pose {
  return {pose.position, toQuaternion(toEigen(pose.orientation).normalized())};
}

auto orientationError(const Eigen::Quaterniond& target, const Eigen::Quaterniond& current)
    -> Eigen::Vector3d {
  Eigen::Quaterniond delta = target * current.conjugate();
  if (delta.w() < 0) delta.coeffs() = -delta.coeffs();
  const Eigen::AngleAxisd axisAngle(delta.normalized());
  return axisAngle.axis() * axisAngle.angle();
}

}  // namespace smachac::sim::detail
