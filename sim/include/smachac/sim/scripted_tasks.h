// The paper's pick_block and place_block sub-scripts written by hand against the sim API:
// the reference sequence that generated C++ reproduces state by state, used by the physical
// tests and the benchmark. Each step's failure is reported by name, never thrown.
//
//   pickBlock:  IK hover (pick pose + hover offset) -> move -> open -> IK grip pose -> move
//               -> close (a grasp must be detected) -> move back to the hover joints
//   placeBlock: IK hover above the place pose -> move -> IK place pose -> move -> open
//               -> move back to the hover joints
#pragma once

#include <string>

#include "smachac/sim/limb.h"
#include "smachac/sim/types.h"

namespace smachac::sim {

class Ik;
class World;

struct TaskOptions {
  double hover_offset = 0.15;  ///< m, along the base frame's +z
  MoveOptions move{};          ///< for every arm move
};

struct TaskResult {
  bool ok = false;
  std::string failed_step{};  ///< e.g. "IK_PICK_BLOCK_HOVER_POSE"; empty when ok
  std::string detail{};       ///< why it failed
};

/// The demo's overhead gripper orientation (gripper z down, fingers closing along base y).
Quaternion overheadOrientation();

/// Picks the block whose TCP grip pose is `pickPose` (base frame) with `side`'s arm; fails
/// unless the block is still held at the hover pose.
TaskResult pickBlock(World& world, Ik& ik, Side side, const Pose& pick_pose,
                     const TaskOptions& options = {});

/// Puts the held block down with its TCP release pose at `placePose` (base frame).
TaskResult placeBlock(World& world, Ik& ik, Side side, const Pose& place_pose,
                      const TaskOptions& options = {});

}  // namespace smachac::sim
