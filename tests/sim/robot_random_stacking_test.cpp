// Robustness of the stacking machine itself (built as smachac generates it from
// examples/baxter/stacking.yml): 20 seeded random placements of the two blocks, each moved up
// to ±3 cm in x and y from the script's poses, with the script's pick poses following the
// blocks (as a perception step would give them). Placements whose blocks would overlap or
// leave the gripper's fingers no room (centres closer than 8 cm) are drawn again. Every run
// must end `succeeded` with block 2 resting on block 1 and no MuJoCo warning.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "robot_machines.h"

namespace smachac::robot::test {
namespace {

constexpr int kTrials = 20;
constexpr double kSpread = 0.03;
constexpr double kMinSeparation = 0.08;

struct Placement {
  double x1, y1, x2, y2;
};

Placement drawPlacement(std::mt19937& random) {
  std::uniform_real_distribution<double> offset(-kSpread, kSpread);
  for (;;) {
    const Placement p{0.7 + offset(random), 0.15 + offset(random), 0.8 + offset(random),
                      0.15 + offset(random)};
    if (std::hypot(p.x1 - p.x2, p.y1 - p.y2) >= kMinSeparation) return p;
  }
}

}  // namespace

TEST_SUITE("sim_robot_stacking_random") {
  TEST_CASE("stacking.yml stacks the blocks for 20 seeded random placements") {
    std::mt19937 random(20261121);
    int stacked = 0;
    double worst_horizontal = 0.0;
    for (int trial = 0; trial < kTrials; ++trial) {
      const Placement p = drawPlacement(random);
      auto robot = makeRobot();
      auto sm = buildStacking(*robot);
      setBlockPlacement(*sm, 1, p.x1, p.y1);
      setBlockPlacement(*sm, 2, p.x2, p.y2);
      const rt::RunResult result = rt::run(*sm);
      const SceneReport report = finishBaxter(*robot);
      INFO("trial " << trial << ": block1 at (" << p.x1 << ", " << p.y1 << "), block2 at (" << p.x2
                    << ", " << p.y2 << "): " << result.outcome << " " << result.error << ", |dxy| "
                    << report.stack.horizontal << " m, |dz - size| " << report.stack.height_error
                    << " m");
      CHECK(result.outcome == "succeeded");
      CHECK(report.stack.upper == "block2");
      CHECK(report.stack.lower == "block1");
      CHECK(report.stack.stacked);
      CHECK(report.warnings.empty());
      if (result.outcome == "succeeded" && report.stack.stacked) ++stacked;
      worst_horizontal = std::max(worst_horizontal, report.stack.horizontal);
    }
    MESSAGE(stacked << "/" << kTrials << " stacked, worst |dxy| " << worst_horizontal * 1000
                    << " mm");
    CHECK(stacked == kTrials);
  }
}

}  // namespace smachac::robot::test
