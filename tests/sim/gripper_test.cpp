// Gripper: jaw gaps, closing on nothing, grasp detection, and a dropped block detected.
#include <doctest/doctest.h>

#include "sim_test_support.h"
#include "smachac/sim/gripper.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

// Moves the left arm to a TCP pose, failing the test if it cannot.
void moveLeftTo(World& world, Ik& ik, const Pose& target) {
  const IkResult solution = ik.solve(Side::Left, target);
  REQUIRE(solution.ok());
  REQUIRE(world.limb(Side::Left).moveToJointPositions(solution.joints, {.speed = 0.6}).ok());
}

TEST_SUITE("sim_gripper") {
  TEST_CASE("open and close on nothing: slot-3 jaw gaps") {
    auto world = loadWorld();
    Gripper& gripper = world->gripper(Side::Right);
    const GripperResult opened = gripper.open();
    CHECK(opened.status == GripperStatus::Opened);
    CHECK(opened.gap == doctest::Approx(0.0767).epsilon(0.01));
    const GripperResult closed = gripper.close();
    CHECK(closed.status == GripperStatus::ClosedEmpty);
    CHECK_FALSE(closed.ok());
    CHECK(closed.gap == doctest::Approx(0.035).epsilon(0.01));
    CHECK(closed.held_body.empty());
    CHECK(gripper.side() == Side::Right);
  }

  TEST_CASE("closing around a block detects the grasp; opening in the air drops it") {
    auto world = loadWorld();
    Ik ik(*world);
    putBlockOnTable(*world, "block1", kPose1);
    REQUIRE(
        world->limb(Side::Left).moveToJointPositions(untuckPose(Side::Left), {.speed = 1.0}).ok());
    Gripper& gripper = world->gripper(Side::Left);
    REQUIRE(gripper.open().ok());
    moveLeftTo(*world, ik, gripPose({kPose1.x, kPose1.y, kPose1.z + kHoverOffset}));
    moveLeftTo(*world, ik, gripPose(kPose1));

    const GripperResult grasped = gripper.close();
    CHECK(grasped.status == GripperStatus::Grasped);
    CHECK(grasped.held_body == "block1");
    CHECK(grasped.gap == doctest::Approx(kBlockSize).epsilon(0.1));

    moveLeftTo(*world, ik, gripPose({kPose1.x, kPose1.y, kPose1.z + kHoverOffset}));
    CHECK(gripper.heldBody() == "block1");
    CHECK(centreOf(*world, "block1").z > kBlockRestZ + 0.1);

    REQUIRE(gripper.open().ok());
    world->stepFor(1.0);
    CHECK_FALSE(gripper.heldBody().has_value());
    CHECK(centreOf(*world, "block1").z == doctest::Approx(kBlockRestZ).epsilon(0.05));
    CHECK_FALSE(world->hasWarnings());
  }

  TEST_CASE("a position command moves the fingers to that fraction of their travel") {
    auto world = loadWorld();
    Gripper& gripper = world->gripper(Side::Right);
    world->stepFor(0.5);
    CHECK(gripper.opening() == doctest::Approx(1.0).epsilon(0.01));
    CHECK_FALSE(gripper.moving());
    gripper.commandOpening(0.5);
    world->step(5);
    CHECK(gripper.moving());
    world->stepFor(1.0);
    CHECK_FALSE(gripper.moving());
    CHECK(gripper.opening() == doctest::Approx(0.5).epsilon(0.02));
    CHECK(gripper.gap() == doctest::Approx((0.035 + 0.077) / 2).epsilon(0.03));
    gripper.commandOpening(-3.0);  // clamped: closed
    world->stepFor(1.0);
    CHECK(gripper.opening() < 0.01);
    CHECK(gripper.fingerForce() < 1.0);  // closed on nothing: no squeeze left
  }
}

}  // namespace
}  // namespace smachac::sim::test
