// Baxter's standard joint poses, as Rethink Robotics' SDK publishes them: neutral, untuck (the
// pick-and-place demo's start pose) and tuck, for either arm. The right arm mirrors the left:
// s0, e0, w0 and w2 change sign.
#pragma once

#include "smachac/sim/types.h"

namespace smachac::sim {

/// `Limb.move_to_neutral` of baxter_interface: 0, -0.55, 0, 0.75, 0, 1.26, 0 (both arms).
JointPositions neutralPose(Side side);

/// `tuck_arms.py -u`, the demo's start pose: left -0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.50.
JointPositions untuckPose(Side side);

/// `tuck_arms.py -t`: left -1.0, -2.07, 3.0, 2.55, 0.0, 0.01, 0.0.
JointPositions tuckPose(Side side);

/// Mirrors a pose of one arm onto the other arm (flips s0, e0, w0 and w2).
JointPositions mirrorPose(const JointPositions& joints);

}  // namespace smachac::sim
