// The final scene report of a Baxter program: where the blocks are, and whether one rests on
// the other. The verdict uses the physical tests' thresholds: the upper block is centred on
// the lower within 15 mm and sits one block size higher within 5 mm.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "smachac/sim/types.h"
#include "smachac/sim/world.h"

namespace smachac::robot {

inline constexpr double kBlockSize = 0.05;                // m, the scene's cubes
inline constexpr double kStackedHorizontalLimit = 0.015;  // m, |Δxy| of stacked blocks
inline constexpr double kStackedHeightLimit = 0.005;      // m, |Δz - block size|

struct BlockReport {
  std::string name;
  sim::Vec3 centre{};  ///< base frame
};

struct StackVerdict {
  std::string upper;
  std::string lower;
  double horizontal = 0.0;    ///< |Δxy| of the centres (m)
  double height_error = 0.0;  ///< |Δz - block size| (m)
  bool stacked = false;
};

struct SceneReport {
  double time = 0.0;  ///< simulated seconds
  std::vector<BlockReport> blocks;
  StackVerdict stack;  ///< the higher of block1 and block2 judged against the lower
  std::vector<sim::WarningCount> warnings;
};

/// Whether `upper` rests on `lower` (missing bodies: not stacked).
StackVerdict stackVerdict(const sim::World& world, std::string_view upper, std::string_view lower);
SceneReport sceneReport(const sim::World& world);
/// Readable lines: time, each block, the verdict, MuJoCo warnings.
void printReport(std::ostream& out, const SceneReport& report);

}  // namespace smachac::robot
