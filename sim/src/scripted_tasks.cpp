// pickBlock / placeBlock: the pick_block and place_block sub-scripts as straight-line code.
#include "smachac/sim/scripted_tasks.h"

#include <string>

#include "smachac/sim/gripper.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/world.h"

namespace smachac::sim {
namespace {

TaskResult failure(std::string step, std::string detail) {
  return {false, std::move(step), std::move(detail)};
}

Pose raised(const Pose& pose, double offset) {
  Pose hover = pose;
  hover.position.z += offset;
  return hover;
}

std::string timedOut(const MoveResult& moved) {
  return "move timed out " + std::to_string(moved.max_error) + " rad from the goal";
}

// Runs IK then moves there; on success `joints` holds the solution.
TaskResult reach(World& world, Ik& ik, Side side, const Pose& target, const TaskOptions& options,
                 const std::string& name, JointPositions& joints) {
  const IkResult solution = ik.solve(side, target);
  if (!solution.ok()) {
    return failure("IK_" + name, "no IK solution (position error " +
                                     std::to_string(solution.position_error) + " m)");
  }
  joints = solution.joints;
  const MoveResult moved = world.limb(side).moveToJointPositions(joints, options.move);
  if (!moved.ok()) return failure("MOVE_TO_" + name, timedOut(moved));
  return {true, "", ""};
}

TaskResult moveBack(World& world, Side side, const JointPositions& joints,
                    const TaskOptions& options, const std::string& name) {
  const MoveResult moved = world.limb(side).moveToJointPositions(joints, options.move);
  if (!moved.ok()) return failure(name, timedOut(moved));
  return {true, "", ""};
}

}  // namespace

Quaternion overheadOrientation() {
  // ik_pick_and_place_demo.py's (x, y, z, w) = (-0.0249590815779, 0.999649402929,
  // 0.00737916180073, 0.00486450832011), scalar first here.
  return {0.00486450832011, -0.0249590815779, 0.999649402929, 0.00737916180073};
}

TaskResult pickBlock(World& world, Ik& ik, Side side, const Pose& pick_pose,
                     const TaskOptions& options) {
  JointPositions hover{};
  JointPositions grip{};
  TaskResult step = reach(world, ik, side, raised(pick_pose, options.hover_offset), options,
                          "PICK_BLOCK_HOVER_POSE", hover);
  if (!step.ok) return step;
  if (!world.gripper(side).open().ok()) return failure("OPEN_GRIPPER", "gripper did not open");
  step = reach(world, ik, side, pick_pose, options, "PICK_BLOCK_GRIP_POSE", grip);
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

TaskResult placeBlock(World& world, Ik& ik, Side side, const Pose& place_pose,
                      const TaskOptions& options) {
  JointPositions hover{};
  JointPositions release{};
  TaskResult step = reach(world, ik, side, raised(place_pose, options.hover_offset), options,
                          "PLACE_BLOCK_HOVER_POSE", hover);
  if (!step.ok) return step;
  step = reach(world, ik, side, place_pose, options, "PLACE_BLOCK_RELEASE_POSE", release);
  if (!step.ok) return step;
  if (!world.gripper(side).open().ok()) return failure("OPEN_GRIPPER", "gripper did not open");
  return moveBack(world, side, hover, options, "MOVE_TO_PLACE_BLOCK_HOVER_POSE");
}

}  // namespace smachac::sim
