// The userdata formats of the robot states: how poses, offsets, joint positions, limbs and
// frames are written as runtime Values (that is, as plain YAML data in a script).
//
//   pose             [[x, y, z], [qx, qy, qz, qw]]  (SMACHA's Baxter scripts; also what the
//                    states write) or the flat [x, y, z, qx, qy, qz, qw]; metres, a quaternion
//                    in ROS order (w last), normalised when read
//   offset           a pose whose position is added and whose rotation, unless it is all zeros
//                    (the scripts' [0, 0, 0, 0]), is applied after the pose's; also [x, y, z]
//   joint positions  [s0, s1, e0, e1, w0, w1, w2] in radians (a list holding one such list is
//                    accepted too, as Baxter's MoveToJointPositionsState did)
//   joint points     a list of joint positions (a trajectory's waypoints)
//   limb             "left" or "right"
//   frame            "base" (Baxter's base, where poses for IK are given) or "world" (MuJoCo's
//                    world; Gazebo's default); "" means world
//
// A value in another shape throws FormatError, whose message says what was expected.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "smachac/runtime/errors.h"
#include "smachac/runtime/value.h"
#include "smachac/sim/types.h"

namespace smachac::robot {

namespace rt = smachac::runtime;

/// A userdata value or template variable in the wrong shape.
class FormatError : public rt::Error {
 public:
  using rt::Error::Error;
};

sim::Pose parsePose(const rt::Value& value);
sim::Pose parseOffset(const rt::Value& value);
/// `pose` moved by `offset` (see above).
sim::Pose applyOffset(const sim::Pose& pose, const sim::Pose& offset);
sim::JointPositions parseJointPositions(const rt::Value& value);
std::vector<sim::JointPositions> parseJointPoints(const rt::Value& value);
sim::Side parseLimb(std::string_view limb);
sim::Frame parseFrame(std::string_view frame);

/// [[x, y, z], [qx, qy, qz, qw]].
rt::Value poseValue(const sim::Pose& pose);
/// [s0, s1, e0, e1, w0, w1, w2].
rt::Value jointsValue(const sim::JointPositions& joints);

}  // namespace smachac::robot
