// The scene report: block positions and the stacked verdict.
#include "smachac/robot/report.h"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "smachac/sim/bodies.h"

namespace smachac::robot {
namespace {

constexpr const char* kBlocks[] = {"block1", "block2"};

std::string fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string point(const sim::Vec3& v) {
  return "(" + fixed(v.x, 4) + ", " + fixed(v.y, 4) + ", " + fixed(v.z, 4) + ")";
}

}  // namespace

StackVerdict stackVerdict(const sim::World& world, std::string_view upper, std::string_view lower) {
  StackVerdict verdict{std::string(upper), std::string(lower)};
  const auto top = sim::bodyPose(world, upper);
  const auto bottom = sim::bodyPose(world, lower);
  if (!top || !bottom) return verdict;
  const sim::Vec3& a = top->position;
  const sim::Vec3& b = bottom->position;
  verdict.horizontal = std::hypot(a.x - b.x, a.y - b.y);
  verdict.height_error = std::abs(a.z - b.z - kBlockSize);
  verdict.stacked =
      verdict.horizontal < kStackedHorizontalLimit && verdict.height_error < kStackedHeightLimit;
  return verdict;
}

SceneReport sceneReport(const sim::World& world) {
  SceneReport report;
  report.time = world.time();
  for (const char* name : kBlocks) {
    if (auto pose = sim::bodyPose(world, name)) report.blocks.push_back({name, pose->position});
  }
  if (report.blocks.size() == 2) {
    const bool first_higher = report.blocks[0].centre.z > report.blocks[1].centre.z;
    const BlockReport& upper = report.blocks[first_higher ? 0 : 1];
    const BlockReport& lower = report.blocks[first_higher ? 1 : 0];
    report.stack = stackVerdict(world, upper.name, lower.name);
  }
  report.warnings = world.warnings();
  return report;
}

void printReport(std::ostream& out, const SceneReport& report) {
  out << "scene after " << fixed(report.time, 2) << " s simulated\n";
  for (const BlockReport& block : report.blocks) {
    out << "  " << block.name << " at " << point(block.centre) << " (base frame)\n";
  }
  const StackVerdict& stack = report.stack;
  if (!stack.upper.empty()) {
    out << "  " << (stack.stacked ? "stacked: " : "not stacked: ") << stack.upper << " on "
        << stack.lower << " (|dxy| " << fixed(stack.horizontal * 1e3, 1) << " mm, |dz - size| "
        << fixed(stack.height_error * 1e3, 1) << " mm)\n";
  }
  for (const sim::WarningCount& warning : report.warnings) {
    out << "  warning: " << warning.name << " raised " << warning.count << " times\n";
  }
}

}  // namespace smachac::robot
