// examples/baxter/pick_and_place.yml, stacking.yml and dual_arm_stacking.yml with the runtime
// API, state by state. A leaf's `userdata` goes into its parent's scope when the parent is
// built (SMACHA renders it there), after the parent's own.
#include "robot_machines.h"

#include <doctest/doctest.h>

namespace smachac::robot::test {
namespace {

const rt::Keys kOutcomes = {"succeeded", "aborted", "preempted"};
// The scripts' quaternions, [qx, qy, qz, qw].
const rt::List kGripperDown = {-0.02496, 0.99965, 0.00738, 0.00486};
const rt::List kNoRotation = {0.0, 0.0, 0.0, 1.0};
const rt::List kLeftStart = {-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5};
const rt::List kRightStart = {0.08, -1.0, 1.19, 1.94, -0.67, 1.03, 0.5};

// [[x, y, z], [qx, qy, qz, qw]], as the scripts write poses.
rt::Value pose(double x, double y, double z, const rt::List& rotation) {
  return rt::List{rt::List{x, y, z}, rotation};
}

rt::Value hoverOffset() { return pose(0.0, 0.0, 0.15, {0.0, 0.0, 0.0, 0.0}); }

// LOAD_TABLE_MODEL, the same in all three scripts.
void addLoadTableModel(rt::StateMachine& sm, RobotContext& robot, const std::string& next) {
  sm.add("LOAD_TABLE_MODEL",
         std::make_unique<LoadGazeboModelState>(robot, LoadGazeboModelArgs{.model_name = "table"}),
         {{"succeeded", next}},
         {{"pose", "table_model_pose_world"}, {"reference_frame", "table_model_ref_frame"}});
  sm.userdata().set("table_model_pose_world", pose(1.0, 0.0, 0.0, kNoRotation));
  sm.userdata().set("table_model_ref_frame", "world");
}

// LOAD_BLOCK_MODEL_1, the same in stacking.yml and dual_arm_stacking.yml.
void addLoadBlockModel1(rt::StateMachine& sm, RobotContext& robot) {
  sm.add("LOAD_BLOCK_MODEL_1",
         std::make_unique<LoadGazeboModelState>(robot, LoadGazeboModelArgs{.model_name = "block1"}),
         {{"succeeded", "LOAD_BLOCK_MODEL_2"}},
         {{"pose", "block_model_1_pose_base"}, {"reference_frame", "block_model_ref_frame"}});
  setBlockPlacement(sm, 1, 0.7, 0.15);
  sm.userdata().set("block_model_ref_frame", "base");
  sm.userdata().set("block_model_1_place_pose", pose(0.75, 0.0, -0.129, kGripperDown));
}

// LOAD_BLOCK_MODEL_2 of stacking.yml (x = 0.8, y = 0.15) or dual_arm_stacking.yml (0.7, -0.2).
void addLoadBlockModel2(rt::StateMachine& sm, RobotContext& robot, double x, double y,
                        const std::string& next) {
  sm.add("LOAD_BLOCK_MODEL_2",
         std::make_unique<LoadGazeboModelState>(robot, LoadGazeboModelArgs{.model_name = "block2"}),
         {{"succeeded", next}},
         {{"pose", "block_model_2_pose_base"}, {"reference_frame", "block_model_ref_frame"}});
  setBlockPlacement(sm, 2, x, y);
  sm.userdata().set("block_model_2_place_pose", pose(0.75, 0.0, -0.079, kGripperDown));
}

// PICK_AND_PLACE_BLOCK_<n> of stacking.yml.
void addPickAndPlaceBlock(rt::StateMachine& parent, RobotContext& robot, int n,
                          const std::string& next) {
  const std::string block = "block_model_" + std::to_string(n);
  auto& sm =
      parent.add("PICK_AND_PLACE_BLOCK_" + std::to_string(n),
                 std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
                     .outcomes = kOutcomes,
                     .input_keys = {"limb", "pick_pose", "place_pose", "hover_offset"}}),
                 {{"succeeded", next}},
                 {{"pick_pose", block + "_pick_pose"}, {"place_pose", block + "_place_pose"}});
  addPickBlock(sm, robot, "PICK_BLOCK", {{"succeeded", "PLACE_BLOCK"}}, {});
  addPlaceBlock(sm, robot, "PLACE_BLOCK", {{"succeeded", "succeeded"}}, {});
}

// PICK_BLOCK_<n> of dual_arm_stacking.yml: `side` ("LEFT"/"RIGHT") moves to its start, picks.
void addPickBlockN(rt::Concurrence& parent, RobotContext& robot, int n, const std::string& side) {
  const std::string block = "block_" + std::to_string(n);
  const std::string start =
      (side == "LEFT" ? "left" : "right") + std::string("_limb_joint_start_positions");
  auto& sm = parent.add(
      "PICK_BLOCK_" + std::to_string(n),
      std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
          .outcomes = kOutcomes,
          .input_keys = {block + "_limb", start, "block_model_" + std::to_string(n) + "_pick_pose",
                         "hover_offset"}}));
  sm.add("MOVE_" + side + "_LIMB_TO_START_POSITION",
         std::make_unique<MoveToJointPositionsState>(robot), {{"succeeded", "PICK_BLOCK"}},
         {{"limb", block + "_limb"}, {"positions", start}});
  addPickBlock(sm, robot, "PICK_BLOCK", {{"succeeded", "succeeded"}},
               {{"limb", block + "_limb"},
                {"pick_pose", "block_model_" + std::to_string(n) + "_pick_pose"}});
}

// STACK_BLOCKS of dual_arm_stacking.yml.
void addStackBlocks(rt::StateMachine& parent, RobotContext& robot) {
  auto& sm = parent.add("STACK_BLOCKS",
                        std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
                            .outcomes = kOutcomes,
                            .input_keys = {"block_1_limb", "left_limb_joint_start_positions",
                                           "block_model_1_place_pose", "block_2_limb",
                                           "right_limb_joint_start_positions",
                                           "block_model_2_place_pose", "hover_offset"}}),
                        {{"succeeded", "succeeded"}});
  addPlaceBlock(sm, robot, "PLACE_BLOCK_1", {{"succeeded", "MOVE_LEFT_LIMB_TO_START_POSITION"}},
                {{"limb", "block_1_limb"}, {"place_pose", "block_model_1_place_pose"}});
  sm.add("MOVE_LEFT_LIMB_TO_START_POSITION", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "PLACE_BLOCK_2"}},
         {{"limb", "block_1_limb"}, {"positions", "left_limb_joint_start_positions"}});
  addPlaceBlock(sm, robot, "PLACE_BLOCK_2", {{"succeeded", "MOVE_RIGHT_LIMB_TO_START_POSITION"}},
                {{"limb", "block_2_limb"}, {"place_pose", "block_model_2_place_pose"}});
  sm.add("MOVE_RIGHT_LIMB_TO_START_POSITION", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "succeeded"}},
         {{"limb", "block_2_limb"}, {"positions", "right_limb_joint_start_positions"}});
}

}  // namespace

std::unique_ptr<RobotContext> makeRobot(RobotOptions options) {
  sim::LoadResult loaded = sim::World::loadDefault();
  INFO(loaded.error);
  REQUIRE(loaded.world != nullptr);
  options.quiet = true;
  return std::make_unique<RobotContext>(std::move(loaded.world), std::move(options));
}

std::unique_ptr<rt::StateMachine> buildPickAndPlace(RobotContext& robot) {
  auto sm = std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
      .outcomes = kOutcomes, .userdata = {{"limb", "left"}, {"hover_offset", hoverOffset()}}});
  addLoadTableModel(*sm, robot, "LOAD_BLOCK_MODEL");
  sm->add(
      "LOAD_BLOCK_MODEL",
      std::make_unique<LoadGazeboModelState>(robot, LoadGazeboModelArgs{.model_name = "block1"}),
      {{"succeeded", "MOVE_TO_START_POSITION"}},
      {{"pose", "block_model_pose_base"}, {"reference_frame", "block_model_ref_frame"}});
  sm->userdata().set("block_model_pose_base", pose(0.7, 0.15, -0.13, kNoRotation));
  sm->userdata().set("block_model_ref_frame", "base");
  sm->userdata().set("block_model_pick_pose", pose(0.7, 0.15, -0.129, kGripperDown));
  sm->userdata().set("block_model_place_pose", pose(0.75, 0.0, -0.129, kGripperDown));
  sm->add("MOVE_TO_START_POSITION", std::make_unique<MoveToJointPositionsState>(robot),
          {{"succeeded", "PICK_BLOCK"}}, {{"positions", "joint_start_positions"}});
  sm->userdata().set("joint_start_positions", kLeftStart);
  addPickBlock(*sm, robot, "PICK_BLOCK", {{"succeeded", "PLACE_BLOCK"}},
               {{"pick_pose", "block_model_pick_pose"}});
  addPlaceBlock(*sm, robot, "PLACE_BLOCK", {{"succeeded", "succeeded"}},
                {{"place_pose", "block_model_place_pose"}});
  return sm;
}

void setBlockPlacement(rt::StateMachine& sm, int n, double x, double y) {
  const std::string block = "block_model_" + std::to_string(n);
  sm.userdata().set(block + "_pose_base", pose(x, y, -0.13, kNoRotation));
  sm.userdata().set(block + "_pick_pose", pose(x, y, -0.129, kGripperDown));
}

std::unique_ptr<rt::StateMachine> buildStacking(RobotContext& robot) {
  auto sm = std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
      .outcomes = kOutcomes, .userdata = {{"limb", "left"}, {"hover_offset", hoverOffset()}}});
  addLoadTableModel(*sm, robot, "LOAD_BLOCK_MODEL_1");
  addLoadBlockModel1(*sm, robot);
  addLoadBlockModel2(*sm, robot, 0.8, 0.15, "MOVE_TO_START_POSITION");
  sm->add("MOVE_TO_START_POSITION", std::make_unique<MoveToJointPositionsState>(robot),
          {{"succeeded", "PICK_AND_PLACE_BLOCK_1"}}, {{"positions", "joint_start_positions"}});
  sm->userdata().set("joint_start_positions", kLeftStart);
  addPickAndPlaceBlock(*sm, robot, 1, "PICK_AND_PLACE_BLOCK_2");
  addPickAndPlaceBlock(*sm, robot, 2, "succeeded");
  return sm;
}

std::unique_ptr<rt::StateMachine> buildDualArmStacking(RobotContext& robot) {
  auto sm = std::make_unique<rt::StateMachine>(
      rt::StateMachineSpec{.outcomes = kOutcomes,
                           .userdata = {{"block_1_limb", "left"},
                                        {"block_2_limb", "right"},
                                        {"left_limb_joint_start_positions", kLeftStart},
                                        {"right_limb_joint_start_positions", kRightStart},
                                        {"hover_offset", hoverOffset()}}});
  addLoadTableModel(*sm, robot, "LOAD_BLOCK_MODEL_1");
  addLoadBlockModel1(*sm, robot);
  addLoadBlockModel2(*sm, robot, 0.7, -0.2, "PICK_BLOCKS");
  auto& pick =
      sm->add("PICK_BLOCKS",
              std::make_unique<rt::Concurrence>(rt::ConcurrenceSpec{
                  .outcomes = kOutcomes,
                  .default_outcome = "aborted",
                  .outcome_map = {{"succeeded",
                                   {{"PICK_BLOCK_1", "succeeded"}, {"PICK_BLOCK_2", "succeeded"}}},
                                  {"preempted",
                                   {{"PICK_BLOCK_1", "preempted"}, {"PICK_BLOCK_2", "preempted"}}}},
                  .input_keys = {"block_1_limb", "left_limb_joint_start_positions",
                                 "block_model_1_pick_pose", "block_2_limb",
                                 "right_limb_joint_start_positions", "block_model_2_pick_pose",
                                 "hover_offset"}}),
              {{"succeeded", "STACK_BLOCKS"}});
  addPickBlockN(pick, robot, 1, "LEFT");
  addPickBlockN(pick, robot, 2, "RIGHT");
  addStackBlocks(*sm, robot);
  return sm;
}

}  // namespace smachac::robot::test
