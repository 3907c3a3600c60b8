// Everything a generated Baxter program needs: the robot context, BaxterBase's start-up and
// report, the userdata formats and every Baxter state class.
#pragma once

#include "smachac/robot/baxter_base.h"
#include "smachac/robot/formats.h"
#include "smachac/robot/gripper_interface_state.h"
#include "smachac/robot/load_model_state.h"
#include "smachac/robot/move_states.h"
#include "smachac/robot/pose_to_joint_traj_service_state.h"
#include "smachac/robot/read_endpoint_pose_state.h"
#include "smachac/robot/report.h"
#include "smachac/robot/robot_context.h"
#include "smachac/robot/robot_state.h"
