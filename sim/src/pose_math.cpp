// Pose conversions and rigid-body math on Eigen.
#include "pose_math.h"

#include <cmath>

namespace smachac::sim::detail {

Eigen::Vector3d toEigen(const Vec3& v) { return {v.x, v.y, v.z}; }

Eigen::Quaterniond toEigen(const Quaternion& q) { return {q.w, q.x, q.y, q.z}; }

Vec3 toVec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Quaternion toQuaternion(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

Pose poseFromMujoco(const double* position, const double* matrix) {
  Eigen::Matrix3d rotation;
  rotation << matrix[0], matrix[1], matrix[2], matrix[3], matrix[4], matrix[5], matrix[6],
      matrix[7], matrix[8];
  Eigen::Quaterniond q(rotation);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return {{position[0], position[1], position[2]}, toQuaternion(q.normalized())};
}

Pose compose(const Pose& a, const Pose& b) {
  const Eigen::Quaterniond qa = toEigen(a.orientation);
  const Eigen::Vector3d p = toEigen(a.position) + qa * toEigen(b.position);
  return {toVec3(p), toQuaternion((qa * toEigen(b.orientation)).normalized())};
}

Pose inverse(const Pose& pose) {
  const Eigen::Quaterniond qi = toEigen(pose.orientation).conjugate();
  return {toVec3(-(qi * toEigen(pose.position))), toQuaternion(qi)};
}

bool isValidPose(const Pose& pose) {
  const double values[] = {pose.position.x,    pose.position.y,    pose.position.z,
                           pose.orientation.w, pose.orientation.x, pose.orientation.y,
                           pose.orientation.z};
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return toEigen(pose.orientation).norm() > 1e-6;
}

Pose normalized(const Pose& pose) {
  return {pose.position, toQuaternion(toEigen(pose.orientation).normalized())};
}

Eigen::Vector3d orientationError(const Eigen::Quaterniond& target,
                                 const Eigen::Quaterniond& current) {
  Eigen::Quaterniond delta = target * current.conjugate();
  if (delta.w() < 0) delta.coeffs() = -delta.coeffs();
  const Eigen::AngleAxisd axis_angle(delta.normalized());
  return axis_angle.axis() * axis_angle.angle();
}

}  // namespace smachac::sim::detail
