// The paper's three experiments, physically: pick and place, stacking (two pick-and-place
// sequences) and dual-arm stacking (both arms pick at the same time), written against the sim
// API as the generated C++ will run them. Blocks must end where the script puts them.
#include <doctest/doctest.h>

#include <cmath>
#include <thread>

#include "sim_test_support.h"
#include "smachac/sim/gripper.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/scripted_tasks.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

// A third spot on the table, between the demo poses, where the one-arm stack is built.
constexpr Vec3 kStackPose{0.65, -0.05, -0.129};
// Dual arm: the right arm's block mirrors pose 1 a little further out, so that the right
// gripper waiting at its hover pose stays clear of the left arm stacking at pose 2.
constexpr Vec3 kRightPickPose{0.7, -0.2, -0.129};

Vec3 above(const Vec3& v, double dz) { return {v.x, v.y, v.z + dz}; }

void moveToStart(World& world, Side side) {
  REQUIRE(world.limb(side).moveToJointPositions(untuckPose(side)).ok());
}

void requireTask(const TaskResult& result) {
  INFO("failed step " << result.failed_step << ": " << result.detail);
  REQUIRE(result.ok);
}

// upper rests on lower: centred within 15 mm, one block size higher within 5 mm.
void checkStacked(const World& world, const char* upper, const char* lower) {
  const Vec3 top = centreOf(world, upper);
  const Vec3 bottom = centreOf(world, lower);
  INFO(upper << " at " << top.x << " " << top.y << " " << top.z << ", " << lower << " at "
             << bottom.x << " " << bottom.y << " " << bottom.z);
  CHECK(horizontalDistance(top, bottom) < 0.015);
  CHECK(std::abs(top.z - bottom.z - kBlockSize) < 0.005);
}

void checkNoWarnings(const World& world) {
  for (const WarningCount& warning : world.warnings()) {
    FAIL_CHECK(warning.name << " raised " << warning.count << " times");
  }
}

TEST_SUITE("sim_tasks") {
  TEST_CASE("pick and place moves the block within 1 cm of its target") {
    auto world = loadWorld();
    Ik ik(*world);
    putBlockOnTable(*world, "block1", kPose1);
    moveToStart(*world, Side::Left);
    requireTask(
        pickBlock(*world, ik, Side::Left, gripPoseForBlock({kPose1.x, kPose1.y, kBlockRestZ})));
    requireTask(placeBlock(*world, ik, Side::Left, gripPose(kPose2)));
    world->stepFor(1.0);
    const Vec3 target{kPose2.x, kPose2.y, kBlockRestZ};
    const Vec3 placed = centreOf(*world, "block1");
    INFO("block at " << placed.x << " " << placed.y << " " << placed.z);
    CHECK(distance(placed, target) < 0.01);
    CHECK_FALSE(world->gripper(Side::Left).heldBody().has_value());
    checkNoWarnings(*world);
    MESSAGE("pick and place: " << world->time() << " s simulated, real-time factor "
                               << world->realTimeFactor());
  }

  TEST_CASE("stacking: two pick-and-place sequences leave block 1 on block 2") {
    auto world = loadWorld();
    Ik ik(*world);
    putBlockOnTable(*world, "block1", kPose1);
    putBlockOnTable(*world, "block2", kPose2);
    moveToStart(*world, Side::Left);
    // PICK_AND_PLACE_BLOCK_1: block 2 to the stacking spot.
    requireTask(pickBlock(*world, ik, Side::Left, gripPose(kPose2)));
    requireTask(placeBlock(*world, ik, Side::Left, gripPose(kStackPose)));
    // PICK_AND_PLACE_BLOCK_2: block 1 on top of it, one block size higher.
    requireTask(pickBlock(*world, ik, Side::Left, gripPose(kPose1)));
    requireTask(placeBlock(*world, ik, Side::Left, gripPose(above(kStackPose, kBlockSize))));
    world->stepFor(1.0);
    checkStacked(*world, "block1", "block2");
    CHECK(horizontalDistance(centreOf(*world, "block2"), kStackPose) < 0.01);
    checkNoWarnings(*world);
  }

  TEST_CASE("dual arm, one thread: both arms pick at the same time, then stack") {
    auto world = loadWorld();
    Ik ik(*world);
    putBlockOnTable(*world, "block1", kPose1);
    putBlockOnTable(*world, "block2", kRightPickPose);
    const Side sides[] = {Side::Left, Side::Right};
    const Vec3 picks[] = {kPose1, kRightPickPose};
    JointPositions hover[2];
    JointPositions grip[2];
    for (int i = 0; i < 2; ++i) {
      const IkResult h = ik.solveFromSeeds(
          sides[i], world->toWorld(gripPose(above(picks[i], kHoverOffset)), Frame::Base),
          std::array<JointPositions, 1>{untuckPose(sides[i])}, {});
      REQUIRE(h.ok());
      hover[i] = h.joints;
      const IkResult g =
          ik.solveFromSeeds(sides[i], world->toWorld(gripPose(picks[i]), Frame::Base),
                            std::array<JointPositions, 1>{hover[i]}, {});
      REQUIRE(g.ok());
      grip[i] = g.joints;
    }
    auto both_move = [&](const JointPositions(&goals)[2]) {
      for (int i = 0; i < 2; ++i) REQUIRE(world->limb(sides[i]).startMove(goals[i]));
      REQUIRE(world->stepUntil(
          [&] { return world->limb(Side::Left).moveDone() && world->limb(Side::Right).moveDone(); },
          15.0));
    };
    const JointPositions start[2] = {untuckPose(Side::Left), untuckPose(Side::Right)};
    both_move(start);
    both_move(hover);
    both_move(grip);
    for (Side side : sides) world->gripper(side).commandClose();
    world->stepFor(0.5);
    both_move(hover);
    CHECK(world->gripper(Side::Left).heldBody() == "block1");
    CHECK(world->gripper(Side::Right).heldBody() == "block2");
    // STACK_BLOCKS: left puts block 1 down at pose 2 and goes back to its start pose (out of
    // the way), right puts block 2 on top.
    requireTask(placeBlock(*world, ik, Side::Left, gripPose(kPose2)));
    moveToStart(*world, Side::Left);
    requireTask(placeBlock(*world, ik, Side::Right, gripPose(above(kPose2, kBlockSize))));
    world->stepFor(1.0);
    checkStacked(*world, "block2", "block1");
    checkNoWarnings(*world);
  }

  TEST_CASE("dual arm, two threads: concurrent blocking picks share one world") {
    auto world = loadWorld();
    putBlockOnTable(*world, "block1", kPose1);
    putBlockOnTable(*world, "block2", kRightPickPose);
    TaskResult results[2];
    auto pick = [&](Side side, const Vec3& pose, TaskResult& result) {
      Ik ik(*world);  // one solver per thread: each owns its scratch data
      if (!world->limb(side).moveToJointPositions(untuckPose(side)).ok()) return;
      result = pickBlock(*world, ik, side, gripPose(pose));
    };
    std::thread left(pick, Side::Left, kPose1, std::ref(results[0]));
    std::thread right(pick, Side::Right, kRightPickPose, std::ref(results[1]));
    left.join();
    right.join();
    requireTask(results[0]);
    requireTask(results[1]);
    CHECK(world->gripper(Side::Left).heldBody() == "block1");
    CHECK(world->gripper(Side::Right).heldBody() == "block2");
    checkNoWarnings(*world);
  }
}

}  // namespace
}  // namespace smachac::sim::test
