// Robustness: stacking succeeds for 20 seeded random block placements, each block moved up
// to ±3 cm in x and y from the demo poses. The script targets the blocks' actual poses (as
// LoadGazeboModelState puts them where the script says). Deterministic: fixed seeds.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "sim_test_support.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/limb.h"
#include "smachac/sim/scripted_tasks.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::sim::test {
namespace {

constexpr int kTrials = 20;
constexpr double kSpread = 0.03;

Vec3 jitter(const Vec3& pose, std::mt19937& random) {
  std::uniform_real_distribution<double> offset(-kSpread, kSpread);
  const double dx = offset(random);
  const double dy = offset(random);
  return {pose.x + dx, pose.y + dy, pose.z};
}

// One trial: block 1 near pose 1 is stacked on block 2 near pose 2. Returns success.
bool stackOnce(World& world, Ik& ik, unsigned seed) {
  std::mt19937 random(seed);
  const Vec3 lower = jitter(kPose2, random);
  const Vec3 upper = jitter(kPose1, random);
  world.reset();
  putBlockOnTable(world, "block1", upper);
  putBlockOnTable(world, "block2", lower);
  if (!world.limb(Side::Left).moveToJointPositions(untuckPose(Side::Left), {.speed = 0.6}).ok()) {
    return false;
  }
  const TaskOptions options{.move = {.speed = 0.5}};
  if (!pickBlock(world, ik, Side::Left, gripPose(upper), options).ok) return false;
  const Vec3 release{lower.x, lower.y, lower.z + kBlockSize};
  if (!placeBlock(world, ik, Side::Left, gripPose(release), options).ok) return false;
  world.stepFor(1.0);
  const Vec3 top = centreOf(world, "block1");
  const Vec3 bottom = centreOf(world, "block2");
  INFO("seed " << seed << ": dxy " << horizontalDistance(top, bottom) << " dz "
               << top.z - bottom.z);
  return horizontalDistance(top, bottom) < 0.015 &&
         std::abs(top.z - bottom.z - kBlockSize) < 0.005 && !world.hasWarnings();
}

TEST_SUITE("sim_robustness") {
  TEST_CASE("stacking succeeds for 20 seeded random placements within ±3 cm") {
    auto world = loadWorld();
    Ik ik(*world);
    int succeeded = 0;
    for (unsigned seed = 1; seed <= kTrials; ++seed) {
      const bool ok = stackOnce(*world, ik, seed);
      CHECK_MESSAGE(ok, "stacking failed for seed " << seed);
      succeeded += ok ? 1 : 0;
    }
    MESSAGE(succeeded << "/" << kTrials << " stacked; real-time factor of the last trial "
                      << world->realTimeFactor());
    CHECK(succeeded == kTrials);
  }
}

}  // namespace
}  // namespace smachac::sim::test
