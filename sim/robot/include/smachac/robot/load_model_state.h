// LoadModelState (template LoadGazeboModelState): puts a model of the scene at a pose, as
// Gazebo's spawn service does for the paper's scripts. MuJoCo 2.2 cannot add bodies at run
// time, so the scene declares them (`table`, `block1`, `block2`) and loading one moves it there
// at rest. The pose is the body's frame (a block's centre) in `reference_frame`.
//
//   variable         input key          meaning
//   model_name       -                  the scene body (required)
//   model_path       -                  accepted for Gazebo scripts, unused
//   pose             pose               where (formats.h; the rotation may be all zeros)
//   reference_frame  reference_frame    `world` (default, as Gazebo) or `base`
//
// Outcomes: succeeded; an unknown model or a bad pose throws (a script error).
#pragma once

#include <string>

#include "smachac/robot/robot_state.h"

namespace smachac::robot {

struct LoadModelArgs {
  std::string model_name{};
  std::string model_path{};
  rt::Value pose{};               ///< null: input key `pose`
  std::string reference_frame{};  ///< empty: input key `reference_frame` when set, else world
};

class LoadModelState : public RobotState {
 public:
  LoadModelState(RobotContext& context, LoadModelArgs args = {});

 protected:
  std::string run(rt::UserData& userdata) override;

 private:
  LoadModelArgs args_;
};

/// The paper's template name.
using LoadGazeboModelState = LoadModelState;
using LoadGazeboModelArgs = LoadModelArgs;

}  // namespace smachac::robot
