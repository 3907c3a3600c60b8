// pickBlock / placeBlock: the pick_block and place_block sub-scripts as straight-line code.
#include "smachac/sim/scripted_tasks.h"

#include <string>

#include "smachac/sim/gripper.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

auto failure(std::string step, std::string detail) -> TaskResult {
  return {false, std::move(step), std::move(detail)};
}

auto raised(const Pose& pose, double offset) -> Pose {
  Pose hover = pose;
  hover.position.z += offset;
  return hover;
}

auto timedOut(const MoveResult& moved) -> std::string {
  return "move timed out " + std::to_string(moved.maxError) + " rad from the goal";
}

// Runs IK then moves there; on success `joints` holds the solution.
auto reach(World& world, Ik& ik, Side side, const Pose& target, const TaskOptions& options,
           const std::string& name, JointPositions& joints) -> TaskResult {
  const IkResult solution = ik.solve(side, target);
  if (!solution.ok()) {
    return failure("IK_" + name, "no IK solution (position error " +
                                     std::to_string(solution.positionError) + " m)");
  }
  joints = solution.joints;
  const MoveResult moved = world.limb(side).moveToJointPositions(joints, options.move);
  if (!moved.ok()) return failure("MOVE_TO_" + name, timedOut(moved));
  return {true, "", ""};
}

auto moveBack(World& world, Side side, const JointPositions& joints, const TaskOptions& options,
              const std::string& name) -> TaskResult {
  const MoveResult moved = world.limb(side).moveToJointPositions(joints, options.move);
  if (!moved.ok()) return failure(name, timedOut(moved));
  return {true, "", ""};
}

}  // namespace

auto overheadOrientation() -> Quaternion {
  // ik_pick_and_place_demo.py's (x, y, z, w) = (-0.0249590815779, 0.999649402929,
  // 0.00737916180073, 0.00486450832011), scalar first here.
  return {0.00486450832011, -0.0249590815779, 0.999649402929, 0.00737916180073};
}

auto pickBlock(World& world, Ik& ik, Side side, const Pose& pickPose, const TaskOptions& options)
    -> TaskResult {
  JointPositions hover{};
  JointPositions grip{};
  TaskResult step = reach(world, ik, side, raised(pickPose, options.hoverOffset), options,
                          "PICK_BLOCK_HOVER_POSE", hover);
  if (!step.ok) return step;
  if (!world.gripper(side).open().ok()) return failure("OPEN_GRIPPER", "gripper did not open");
  step = reach(world, ik, side, pickPose, options, "PICK_BLOCK_GRIP_POSE", grip);
  if (!step.ok) return step;
  const GripperResult closed = world.gripper(side).close();
  if (!closed.ok()) return failure("CLOSE_GRIPPER", "no grasp detected");
  step = moveBack(world, side, hover, options, "MOVE_TO_GRIPPED_BLOCK_HOVER_POSE");
  if (!step.ok) return step;
  if (!world.gripper(side).heldBody()) {
    return failure("MOVE_TO_GRIPPED_BLOCK_HOVER_POSE", "block dropped");
  }
  return {true, "", ""};
}

auto placeBlock(World& world, Ik& ik, Side side, const Pose& placePose, const TaskOptions& options)
    -> TaskResult {
  JointPositions hover{};
  JointPositions release{};
  TaskResult step = reach(world, ik, side, raised(placePose, options.hoverOffset), options,
                          "PLACE_BLOCK_HOVER_POSE", hover);
  if (!step.ok) return step;
  step = reach(world, ik, side, placePose, options, "PLACE_BLOCK_RELEASE_POSE", release);
  if (!step.ok) return step;
  if (!world.gripper(side).open().ok()) return failure("OPEN_GRIPPER", "gripper did not open");
  return moveBack(world, side, hover, options, "MOVE_TO_PLACE_BLOCK_HOVER_POSE");
}

}  // namespace smachac::sim
