// Baxter's standard joint poses (the values of Rethink Robotics' published Baxter SDK poses).
#include "smachac/sim/standard_poses.h"

namespace smachac::sim {
namespace {

JointPositions forSide(Side side, const JointPositions& left) {
  return side == Side::Left ? left : mirrorPose(left);
}

}  // namespace

JointPositions mirrorPose(const JointPositions& joints) {
  JointPositions mirrored = joints;
  for (int i : {0, 2, 4, 6}) mirrored[static_cast<size_t>(i)] = -joints[static_cast<size_t>(i)];
  return mirrored;
}

JointPositions neutralPose(Side side) {
  return forSide(side, {0.0, -0.55, 0.0, 0.75, 0.0, 1.26, 0.0});
}

JointPositions untuckPose(Side side) {
  return forSide(side, {-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.50});
}

JointPositions tuckPose(Side side) {
  return forSide(side, {-1.0, -2.07, 3.0, 2.55, 0.0, 0.01, 0.0});
}

}  // namespace smachac::sim
