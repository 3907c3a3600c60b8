// examples/baxter/sub/pick_block.yml and place_block.yml as generated code builds them where
// they are included: the caller's transitions and remapping (SMACHA merges the caller's keys
// into the sub-script's state, the caller's entries winning).
#include "robot_machines.h"

namespace smachac::robot::test {

void addPickBlock(rt::StateMachine& parent, RobotContext& robot, const std::string& label,
                  rt::Transitions transitions, rt::Remapping remapping) {
  auto& sm = parent.add(label,
                        std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
                            .outcomes = {"succeeded", "aborted", "preempted"},
                            .input_keys = {"limb", "pick_pose", "hover_offset"}}),
                        std::move(transitions), std::move(remapping));
  sm.add("IK_PICK_BLOCK_HOVER_POSE", std::make_unique<PoseToJointTrajServiceState>(robot),
         {{"succeeded", "MOVE_TO_PICK_BLOCK_HOVER_POSE"}},
         {{"poses", "pick_pose"},
          {"offsets", "hover_offset"},
          {"joints", "ik_joint_response_block_pick_hover_pose"}});
  sm.add("MOVE_TO_PICK_BLOCK_HOVER_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "OPEN_GRIPPER"}},
         {{"positions", "ik_joint_response_block_pick_hover_pose"}});
  sm.add("OPEN_GRIPPER",
         std::make_unique<GripperInterfaceState>(robot, GripperInterfaceArgs{.command = "open"}),
         {{"succeeded", "IK_PICK_BLOCK_GRIP_POSE"}});
  sm.add("IK_PICK_BLOCK_GRIP_POSE", std::make_unique<PoseToJointTrajServiceState>(robot),
         {{"succeeded", "MOVE_TO_PICK_BLOCK_GRIP_POSE"}},
         {{"poses", "pick_pose"}, {"joints", "ik_joint_response_block_pick_pose"}});
  sm.add("MOVE_TO_PICK_BLOCK_GRIP_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "CLOSE_GRIPPER"}}, {{"positions", "ik_joint_response_block_pick_pose"}});
  sm.add("CLOSE_GRIPPER",
         std::make_unique<GripperInterfaceState>(robot, GripperInterfaceArgs{.command = "close"}),
         {{"succeeded", "MOVE_TO_GRIPPED_BLOCK_HOVER_POSE"}});
  sm.add("MOVE_TO_GRIPPED_BLOCK_HOVER_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "succeeded"}}, {{"positions", "ik_joint_response_block_pick_hover_pose"}});
}

void addPlaceBlock(rt::StateMachine& parent, RobotContext& robot, const std::string& label,
                   rt::Transitions transitions, rt::Remapping remapping) {
  auto& sm = parent.add(label,
                        std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
                            .outcomes = {"succeeded", "aborted", "preempted"},
                            .input_keys = {"limb", "place_pose", "hover_offset"}}),
                        std::move(transitions), std::move(remapping));
  sm.add("IK_PLACE_BLOCK_HOVER_POSE", std::make_unique<PoseToJointTrajServiceState>(robot),
         {{"succeeded", "MOVE_TO_PLACE_BLOCK_HOVER_POSE"}},
         {{"poses", "place_pose"},
          {"offsets", "hover_offset"},
          {"joints", "ik_joint_response_block_place_hover_pose"}});
  sm.add("MOVE_TO_PLACE_BLOCK_HOVER_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "IK_PLACE_BLOCK_RELEASE_POSE"}},
         {{"positions", "ik_joint_response_block_place_hover_pose"}});
  sm.add("IK_PLACE_BLOCK_RELEASE_POSE", std::make_unique<PoseToJointTrajServiceState>(robot),
         {{"succeeded", "MOVE_TO_PLACE_BLOCK_RELEASE_POSE"}},
         {{"poses", "place_pose"}, {"joints", "ik_joint_response_block_place_pose"}});
  sm.add("MOVE_TO_PLACE_BLOCK_RELEASE_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "OPEN_GRIPPER"}}, {{"positions", "ik_joint_response_block_place_pose"}});
  sm.add("OPEN_GRIPPER",
         std::make_unique<GripperInterfaceState>(robot, GripperInterfaceArgs{.command = "open"}),
         {{"succeeded", "READ_RELEASED_BLOCK_ENDPOINT_POSE"}});
  sm.add("READ_RELEASED_BLOCK_ENDPOINT_POSE", std::make_unique<ReadEndpointPoseState>(robot),
         {{"succeeded", "IK_RELEASED_BLOCK_HOVER_POSE"}},
         {{"pose", "released_block_endpoint_pose"}});
  sm.add("IK_RELEASED_BLOCK_HOVER_POSE", std::make_unique<PoseToJointTrajServiceState>(robot),
         {{"succeeded", "MOVE_TO_RELEASED_BLOCK_HOVER_POSE"}},
         {{"poses", "released_block_endpoint_pose"},
          {"offsets", "hover_offset"},
          {"joints", "ik_joint_response_released_block_hover_pose"}});
  sm.add("MOVE_TO_RELEASED_BLOCK_HOVER_POSE", std::make_unique<MoveToJointPositionsState>(robot),
         {{"succeeded", "succeeded"}},
         {{"positions", "ik_joint_response_released_block_hover_pose"}});
}

}  // namespace smachac::robot::test
