// LoadModelState: placing a scene body at a pose.
#include "smachac/robot/load_model_state.h"

#include "smachac/robot/formats.h"
#include "smachac/sim/bodies.h"

namespace smachac::robot {
namespace {

rt::Keys inputs(const LoadModelArgs& args) {
  rt::Keys keys;
  if (args.pose.isNull()) keys.push_back("pose");
  if (args.reference_frame.empty()) keys.push_back("reference_frame");
  return keys;
}

}  // namespace

LoadModelState::LoadModelState(RobotContext& context, LoadModelArgs args)
    : RobotState(context, inputs(args)), args_(std::move(args)) {}

std::string LoadModelState::run(rt::UserData& userdata) {
  const sim::Pose pose = parseOffset(valueOf(args_.pose, "pose", userdata));
  std::string frame = args_.reference_frame;
  if (frame.empty()) frame = userdata.find("reference_frame").value_or("world").as<std::string>();
  switch (sim::placeBody(world(), args_.model_name, pose, parseFrame(frame))) {
    case sim::PlaceStatus::Placed:
      return std::string(kSucceeded);
    case sim::PlaceStatus::UnknownBody:
      throw FormatError("the scene has no model `" + args_.model_name + "`");
    case sim::PlaceStatus::NotMovable:
      throw FormatError("model `" + args_.model_name + "` cannot be moved");
    case sim::PlaceStatus::InvalidPose:
      break;
  }
  throw FormatError("invalid pose for model `" + args_.model_name + "`");
}

}  // namespace smachac::robot
