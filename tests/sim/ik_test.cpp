// Ik: forward kinematics against the published Baxter values, the demo's poses for both arms,
// unreachable and invalid targets as results, joint limits, and the world left untouched.
#include <doctest/doctest.h>

#include <cmath>

#include "sim_test_support.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

Vec3 mirrored(const Vec3& v) { return {v.x, -v.y, v.z}; }

Vec3 raised(const Vec3& v, double dz) { return {v.x, v.y, v.z + dz}; }

TEST_SUITE("sim_ik") {
  TEST_CASE("forward kinematics of untuck and neutral match the published Baxter values") {
    auto world = loadWorld();
    Ik ik(*world);
    for (Side side : {Side::Left, Side::Right}) {
      const double mirror = side == Side::Left ? 1.0 : -1.0;
      const Pose untuck = world->fromWorld(ik.forward(side, untuckPose(side)), Frame::Base);
      CHECK(distance(untuck.position, {0.5797, 0.1833 * mirror, 0.1137}) < 1e-4);
      CHECK(std::abs(untuck.orientation.y) == doctest::Approx(0.990).epsilon(0.001));
      const Pose neutral = world->fromWorld(ik.forward(side, neutralPose(side)), Frame::Base);
      CHECK(distance(neutral.position, {0.6463, 0.8413 * mirror, 0.0626}) < 1e-4);
    }
    const Pose zero = world->fromWorld(ik.forward(Side::Left, JointPositions{}), Frame::Base);
    CHECK(distance(zero.position, {0.9090, 1.1040, 0.3210}) < 1e-4);
  }

  TEST_CASE("the demo's grip, hover and stacking poses are solved for both arms") {
    auto world = loadWorld();
    Ik ik(*world);
    for (Side side : {Side::Left, Side::Right}) {
      for (const Vec3& pose : {kPose1, kPose2, mirrored(kPose1)}) {
        for (double dz : {0.0, kBlockSize, kHoverOffset}) {
          const Pose target = gripPose(raised(pose, dz));
          const IkResult result = ik.solve(side, target);
          INFO("side " << sideName(side) << " target " << pose.x << " " << pose.y << " +" << dz);
          REQUIRE(result.ok());
          CHECK(result.position_error < 1e-4);
          CHECK(result.orientation_error < 1e-3);
          const Pose reached = world->fromWorld(ik.forward(side, result.joints), Frame::Base);
          CHECK(distance(reached.position, target.position) < 1e-4);
          const Limb& limb = world->limb(side);
          for (size_t i = 0; i < result.joints.size(); ++i) {
            CHECK(result.joints[i] >= limb.lowerLimits()[i]);
            CHECK(result.joints[i] <= limb.upperLimits()[i]);
          }
        }
      }
    }
  }

  TEST_CASE("a pose out of reach is an IK failure result") {
    auto world = loadWorld();
    Ik ik(*world);
    const IkResult far = ik.solve(Side::Left, gripPose({2.0, 0.3, 0.0}));
    CHECK(far.status == IkStatus::Unreachable);
    CHECK_FALSE(far.ok());
    CHECK(far.position_error > 0.5);
    CHECK(far.iterations > 0);
    // The right arm cannot reach 1.2 m to the robot's left.
    const IkResult across = ik.solve(Side::Right, gripPose({0.5, 1.2, 0.0}));
    CHECK(across.status == IkStatus::Unreachable);
  }

  TEST_CASE("invalid targets are rejected") {
    auto world = loadWorld();
    Ik ik(*world);
    CHECK(ik.solve(Side::Left, {{NAN, 0.0, 0.0}, {}}).status == IkStatus::InvalidTarget);
    CHECK(ik.solve(Side::Left, {{0.7, 0.1, 0.0}, {0.0, 0.0, 0.0, 0.0}}).status ==
          IkStatus::InvalidTarget);
    CHECK(ik.solve(Side::Left, {{0.7, 0.1, 0.0}, {INFINITY, 0.0, 0.0, 0.0}}).status ==
          IkStatus::InvalidTarget);
  }

  TEST_CASE("targets in the world frame and unnormalised quaternions") {
    auto world = loadWorld();
    Ik ik(*world);
    Pose target = gripPose(kPose1);
    target.position.z += 0.93;
    target.orientation.w *= 3.0;
    target.orientation.x *= 3.0;
    target.orientation.y *= 3.0;
    target.orientation.z *= 3.0;
    CHECK(ik.solve(Side::Left, target, Frame::World).ok());
  }

  TEST_CASE("solving leaves the world untouched") {
    auto world = loadWorld();
    Ik ik(*world);
    const double before = world->time();
    const JointPositions joints = world->limb(Side::Left).jointPositions();
    REQUIRE(ik.solve(Side::Left, gripPose(kPose2)).ok());
    CHECK(world->time() == before);
    CHECK(world->limb(Side::Left).jointPositions() == joints);
  }
}

}  // namespace
}  // namespace smachac::sim::test
