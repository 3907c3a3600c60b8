// Conversions between the API's plain pose types, Eigen and MuJoCo arrays, and the small
// amount of rigid-body math the library needs (composition, inversion, orientation error).
#pragma once

#include <Eigen/Geometry>

#include "smachac/sim/types.h"

namespace smachac::sim::detail {

Eigen::Vector3d toEigen(const Vec3& v);
Eigen::Quaterniond toEigen(const Quaternion& q);
Vec3 toVec3(const Eigen::Vector3d& v);
Quaternion toQuaternion(const Eigen::Quaterniond& q);

/// Pose from a MuJoCo position (3) and rotation matrix (9, row-major).
Pose poseFromMujoco(const double* position, const double* matrix);

/// a * b: b expressed in a's parent frame.
Pose compose(const Pose& a, const Pose& b);
Pose inverse(const Pose& pose);

/// True when every value is finite and the quaternion is not (near) zero.
bool isValidPose(const Pose& pose);
/// The same pose with a unit quaternion.
Pose normalized(const Pose& pose);

/// Rotation vector (axis * angle, world frame) that turns `current` into `target`.
Eigen::Vector3d orientationError(const Eigen::Quaterniond& target,
                                 const Eigen::Quaterniond& current);

}  // namespace smachac::sim::detail
