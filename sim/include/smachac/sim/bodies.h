// Placing and reading free bodies and mocap bodies (the blocks and the table): the simulation's
// form of Gazebo's "spawn model at pose". MuJoCo 2.2 cannot add bodies at run time, so the
// scene declares them and placing one moves it (and stops it).
#pragma once

#include <optional>
#include <string_view>

#include "smachac/sim/types.h"

namespace smachac::sim {

class World;

enum class PlaceStatus {
  Placed,
  UnknownBody,  ///< no body of that name
  NotMovable,   ///< the body has neither a free joint nor a mocap frame
  InvalidPose,  ///< non-finite values or a zero quaternion
};

/// Puts body `name` at `pose` (given in `frame`) at rest. For a block the pose is its centre.
auto placeBody(World& world, std::string_view name, const Pose& pose, Frame frame = Frame::Base)
    -> PlaceStatus;

/// The pose of body `name` in `frame`, or nothing for an unknown body.
auto bodyPose(const World& world, std::string_view name, Frame frame = Frame::Base)
    -> std::optional<Pose>;

}  // namespace smachac::sim
