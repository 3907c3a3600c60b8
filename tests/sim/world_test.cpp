// World: loading (and its failures), forward kinematics against the published Baxter values,
// gravity compensation, reset, determinism, warnings, placing and reading bodies, frames.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "sim_test_support.h"
#include "smachac/sim/bodies.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/model_path.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

TEST_SUITE("sim_world") {
  TEST_CASE("the default scene loads without warnings") {
    auto world = loadWorld();
    CHECK(world->timestep() == doctest::Approx(0.002));
    CHECK(world->time() == 0.0);
    world->stepFor(0.5);
    CHECK(world->time() == doctest::Approx(0.5));
    CHECK_FALSE(world->hasWarnings());
    // Parked blocks rest on the floor (the floor collides).
    for (const char* block : {"block1", "block2"}) {
      const auto parked = bodyPose(*world, block, Frame::World);
      REQUIRE(parked.has_value());
      CHECK(parked->position.z == doctest::Approx(kBlockSize / 2).epsilon(0.02));
    }
  }

  TEST_CASE("a missing or broken model is an error result, not a crash") {
    LoadResult missing = World::load("/nonexistent/scene.xml");
    CHECK(missing.world == nullptr);
    CHECK(missing.error.find("/nonexistent/scene.xml") != std::string::npos);

    const std::string path = "sim_test_not_baxter.xml";
    std::ofstream(path)
        << "<mujoco><worldbody><geom type='sphere' size='0.1'/></worldbody></mujoco>";
    LoadResult not_baxter = World::load(path);
    CHECK(not_baxter.world == nullptr);
    CHECK(not_baxter.error.find("model has no body `base`") != std::string::npos);
    std::remove(path.c_str());
  }

  TEST_CASE("SMACHAC_SIM_MODEL_DIR overrides the model directory") {
    const char* outer = std::getenv("SMACHAC_SIM_MODEL_DIR");
    const std::string saved = outer != nullptr ? outer : "";
    setenv("SMACHAC_SIM_MODEL_DIR", "/elsewhere", 1);
    CHECK(defaultScenePath() == "/elsewhere/scene.xml");
    unsetenv("SMACHAC_SIM_MODEL_DIR");
    CHECK(modelDirectory().find("/elsewhere") == std::string::npos);
    if (outer != nullptr) setenv("SMACHAC_SIM_MODEL_DIR", saved.c_str(), 1);
  }

  TEST_CASE("gravity compensation holds the arms still at q = 0") {
    auto world = loadWorld();
    world->stepFor(2.0);
    for (Side side : {Side::Left, Side::Right}) {
      CHECK(maxJointError(world->limb(side).jointPositions(), JointPositions{}) < 1e-4);
    }
  }

  TEST_CASE("reset restores time, joints and parked blocks") {
    auto world = loadWorld();
    const Vec3 parked = centreOf(*world, "block1");
    putBlockOnTable(*world, "block1", kPose1);
    world->limb(Side::Left).startMove(neutralPose(Side::Left));
    world->stepFor(1.0);
    world->reset();
    CHECK(world->time() == 0.0);
    CHECK(maxJointError(world->limb(Side::Left).jointPositions(), JointPositions{}) == 0.0);
    CHECK(distance(centreOf(*world, "block1"), parked) == 0.0);
  }

  TEST_CASE("runs are deterministic") {
    auto run = [] {
      auto world = loadWorld();
      putBlockOnTable(*world, "block1", kPose1);
      world->limb(Side::Left).moveToJointPositions(untuckPose(Side::Left), {.speed = 1.0});
      return world->limb(Side::Left).endpointPose().position;
    };
    const Vec3 first = run();
    const Vec3 second = run();
    CHECK(first.x == second.x);
    CHECK(first.y == second.y);
    CHECK(first.z == second.z);
  }

  TEST_CASE("placing blocks and the table; unknown and fixed bodies are results") {
    auto world = loadWorld();
    putBlockOnTable(*world, "block2", kPose2);
    world->stepFor(0.5);
    const Vec3 rest = centreOf(*world, "block2");
    CHECK(horizontalDistance(rest, kPose2) < 1e-4);
    CHECK(rest.z == doctest::Approx(kBlockRestZ).epsilon(0.01));
    const auto world_pose = bodyPose(*world, "block2", Frame::World);
    REQUIRE(world_pose.has_value());
    CHECK(world_pose->position.z == doctest::Approx(rest.z + 0.93));

    const Pose table_at{{1.0, 0.0, 0.0}, {}};
    CHECK(placeBody(*world, "table", table_at, Frame::World) == PlaceStatus::Placed);
    CHECK(placeBody(*world, "no_such_body", table_at) == PlaceStatus::UnknownBody);
    CHECK(placeBody(*world, "left_hand", table_at) == PlaceStatus::NotMovable);
    CHECK(placeBody(*world, "block1", {{NAN, 0, 0}, {}}) == PlaceStatus::InvalidPose);
    CHECK_FALSE(bodyPose(*world, "no_such_body").has_value());
  }

  TEST_CASE("a block dropped from above lands on the table, warning free") {
    auto world = loadWorld();
    REQUIRE(placeBody(*world, "block2", {{0.8, -0.2, 0.2}, {}}) == PlaceStatus::Placed);
    world->stepFor(1.5);
    CHECK(centreOf(*world, "block2").z == doctest::Approx(kBlockRestZ).epsilon(0.02));
    CHECK_FALSE(world->hasWarnings());
    CHECK(takeMujocoMessages().empty());
  }

  TEST_CASE("frame conversion: base is 0.93 m above the world origin") {
    auto world = loadWorld();
    const Pose base{{0.1, 0.2, 0.3}, {}};
    const Pose in_world = world->toWorld(base, Frame::Base);
    CHECK(in_world.position.z == doctest::Approx(1.23));
    CHECK(world->fromWorld(in_world, Frame::Base).position.z == doctest::Approx(0.3));
    CHECK(world->toWorld(base, Frame::World).position.z == 0.3);
  }

  TEST_CASE("the real-time factor is measured") {
    auto world = loadWorld();
    world->stepFor(1.0);
    MESSAGE("real-time factor (idle arms): " << world->realTimeFactor());
    CHECK(world->realTimeFactor() > 1.0);
    world->resetTiming();
    CHECK(world->realTimeFactor() == 0.0);
  }
}

}  // namespace
}  // namespace smachac::sim::test
