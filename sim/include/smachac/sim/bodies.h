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
  kPlaced,
  kUnknownBody,  ///< no body of that name
  kNotMovable,   ///< the body has neither a free joint nor a mocap frame
  kInvalidPose,  ///< non-finite values or a zero quaternion
};

/// Puts body `name` at `pose` (given in `frame`) at rest. For a block the pose is its centre.
auto placeBody(World& world, std::string_view name, const Pose& pose, Frame frame = Frame::kBase)
    -> PlaceStatus;

/// The pose of body `name` in `frame`, or nothing for an unknown body.
auto bodyPose(const World& world, std::string_view name, Frame frame = Frame::kBase)
    -> std::optional<Pose>;

}  // namespace smachac::sim
