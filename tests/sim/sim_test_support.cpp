// Scene fixtures and geometric helpers for the simulation tests.
#include "sim_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "smachac/sim/bodies.h"
#include "smachac/sim/scripted_tasks.h"

namespace smachac::sim::test {

std::unique_ptr<World> loadWorld() {
  LoadResult loaded = World::loadDefault();
  INFO(loaded.error);
  REQUIRE(loaded.world != nullptr);
  return std::move(loaded.world);
}

Pose gripPose(const Vec3& tcp) { return {tcp, overheadOrientation()}; }

Pose gripPoseForBlock(const Vec3& centre) {
  return gripPose({centre.x, centre.y, centre.z + 0.001});
}

void putBlockOnTable(World& world, const char* name, const Vec3& tcp) {
  const Pose pose{{tcp.x, tcp.y, kBlockRestZ}, {}};
  REQUIRE(placeBody(world, name, pose) == PlaceStatus::Placed);
}

double maxJointError(const JointPositions& a, const JointPositions& b) {
  double error = 0.0;
  for (size_t i = 0; i < a.size(); ++i) error = std::max(error, std::abs(a[i] - b[i]));
  return error;
}

double distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

double horizontalDistance(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

Vec3 centreOf(const World& world, const char* name) {
  const auto pose = bodyPose(world, name);
  REQUIRE(pose.has_value());
  return pose->position;
}

}  // namespace smachac::sim::test
