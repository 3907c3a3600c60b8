// Conversions between the API's plain pose types, Eigen and MuJoCo arrays, and the small
// amount of rigid-body math the library needs (composition, inversion, orientation error).
#pragma once

#include <Eigen/Geometry>

#include "smachac/sim/types.h"

namespace smachac::sim::detail {

auto toEigen(const Vec3& v) -> Eigen::Vector3d;
auto toEigen(const Quaternion& q) -> Eigen::Quaterniond;
auto toVec3(const Eigen::Vector3d& v) -> Vec3;
auto toQuaternion(const Eigen::Quaterniond& q) -> Quaternion;

/// Pose from a MuJoCo position (3) and rotation matrix (9, row-major).
auto poseFromMujoco(const double* position, const double* matrix) -> Pose;

/// a * b: b expressed in a's parent frame.
auto compose(const Pose& a, const Pose& b) -> Pose;
auto inverse(const Pose& pose) -> Pose;

/// True when every value is finite and the quaternion is not (near) zero.
auto isValidPose(const Pose& pose) -> bool;
/// The same pose with a unit quaternion.
auto normalized(const Pose& pose) -> Pose;

/// Rotation vector (axis * angle, world frame) that turns `current` into `target`.
auto orientationError(const Eigen::Quaterniond& target, const Eigen::Quaterniond& current)
    -> Eigen::Vector3d;

}  // namespace smachac::sim::detail
