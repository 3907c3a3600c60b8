// Limb: moves that reach their goal within tolerance, timeouts and invalid goals as results,
// holding a pose, and both arms moving at once in one world.
#include <doctest/doctest.h>

#include <cmath>

#include "sim_test_support.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

TEST_SUITE("sim_limb") {
  TEST_CASE("moving to untuck reaches it and holds it") {
    auto world = loadWorld();
    Limb& limb = world->limb(Side::Left);
    const MoveResult result = limb.moveToJointPositions(untuckPose(Side::Left));
    REQUIRE(result.ok());
    CHECK(result.max_error <= MoveOptions{}.tolerance);
    CHECK(result.duration > 1.0);  // speed 0.3 of the limit: a smooth move, not a jump
    world->stepFor(1.0);
    CHECK(maxJointError(limb.jointPositions(), untuckPose(Side::Left)) < 1e-3);
    CHECK_FALSE(world->hasWarnings());
  }

  TEST_CASE("joint names follow Baxter's") {
    auto world = loadWorld();
    const auto names = world->limb(Side::Right).jointNames();
    CHECK(names[0] == "right_s0");
    CHECK(names[6] == "right_w2");
    CHECK(world->limb(Side::Left).side() == Side::Left);
  }

  TEST_CASE("a tight timeout gives a timeout result") {
    auto world = loadWorld();
    const MoveResult result =
        world->limb(Side::Left).moveToJointPositions(untuckPose(Side::Left), {.timeout = 0.2});
    CHECK(result.status == MoveStatus::Timeout);
    CHECK_FALSE(result.ok());
    CHECK(result.duration == doctest::Approx(0.2).epsilon(0.02));
    CHECK(result.max_error > 0.1);
  }

  TEST_CASE("goals outside the limits or not finite are rejected without moving") {
    auto world = loadWorld();
    Limb& limb = world->limb(Side::Left);
    JointPositions beyond = neutralPose(Side::Left);
    beyond[1] = 1.5;  // s1 upper limit is 1.047
    CHECK(limb.moveToJointPositions(beyond).status == MoveStatus::InvalidTarget);
    JointPositions not_finite = neutralPose(Side::Left);
    not_finite[3] = NAN;
    CHECK(limb.moveToJointPositions(not_finite).status == MoveStatus::InvalidTarget);
    CHECK_FALSE(limb.startMove(not_finite));
    CHECK(world->time() == 0.0);
  }

  TEST_CASE("both arms move at once in one world") {
    auto world = loadWorld();
    Limb& left = world->limb(Side::Left);
    Limb& right = world->limb(Side::Right);
    REQUIRE(left.startMove(untuckPose(Side::Left)));
    REQUIRE(right.startMove(untuckPose(Side::Right)));
    const bool done = world->stepUntil([&] { return left.moveDone() && right.moveDone(); }, 15.0);
    REQUIRE(done);
    CHECK(left.moveError() <= MoveOptions{}.tolerance);
    CHECK(right.moveError() <= MoveOptions{}.tolerance);
    // Mirror symmetry of the two arms.
    const Pose l = left.endpointPose();
    const Pose r = right.endpointPose();
    CHECK(l.position.x == doctest::Approx(r.position.x).epsilon(1e-3));
    CHECK(l.position.y == doctest::Approx(-r.position.y).epsilon(1e-3));
  }

  TEST_CASE("holdCurrent cancels a move") {
    auto world = loadWorld();
    Limb& limb = world->limb(Side::Left);
    REQUIRE(limb.startMove(neutralPose(Side::Left)));
    world->stepFor(0.5);
    limb.holdCurrent();
    const JointPositions held = limb.jointPositions();
    world->stepFor(1.0);
    CHECK(maxJointError(limb.jointPositions(), held) < 0.02);
    CHECK(limb.moveDone());
  }

  TEST_CASE("streamed position commands are followed at the speed ratio and held") {
    auto world = loadWorld();
    Limb& limb = world->limb(Side::Left);
    const JointPositions goal = untuckPose(Side::Left);
    REQUIRE(limb.commandPositions(goal, 0.3));
    double fastest = 0.0;  // s0 ... e1 are limited to 0.3 * 1.5 rad/s
    double overshoot = 0.0;
    for (int step = 0; step < 4000; ++step) {
      world->step();
      const JointPositions v = limb.jointVelocities();
      const JointPositions q = limb.jointPositions();
      for (size_t i = 0; i < 4; ++i) fastest = std::max(fastest, std::abs(v[i]));
      overshoot = std::max(overshoot, q[3] - goal[3]);  // e1 rises from 0 to 1.94
    }
    CHECK(fastest < 0.3 * 1.5 * 1.05);
    CHECK(fastest > 0.3 * 1.5 * 0.8);
    CHECK(overshoot < 2e-3);
    CHECK(maxJointError(limb.jointPositions(), goal) < 1e-3);
    CHECK_FALSE(world->hasWarnings());
  }

  TEST_CASE("a new streamed command replaces the goal; an invalid one is ignored") {
    auto world = loadWorld();
    Limb& limb = world->limb(Side::Left);
    REQUIRE(limb.commandPositions(untuckPose(Side::Left), 1.0));
    world->stepFor(0.3);
    REQUIRE(limb.commandPositions(neutralPose(Side::Left), 1.0));
    JointPositions beyond = neutralPose(Side::Left);
    beyond[1] = 1.5;
    CHECK_FALSE(limb.commandPositions(beyond, 1.0));
    CHECK_FALSE(limb.commandPositions(neutralPose(Side::Left), NAN));
    world->stepFor(6.0);
    CHECK(maxJointError(limb.jointPositions(), neutralPose(Side::Left)) < 1e-3);
  }
}

}  // namespace
}  // namespace smachac::sim::test
