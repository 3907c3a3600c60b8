// The scene report: block positions and the stacked verdict.
#include "smachac/robot/report.h"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "smachac/sim/bodies.h"

namespace smachac::robot {
namespace {

constexpr const char* kBlocks[] = {"block1", "block2"};

auto fixed(double value, int decimals) -> std::string {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

auto point(const sim::Vec3& v) -> std::string {
  return "(" + fixed(v.x, 4) + ", " + fixed(v.y, 4) + ", " + fixed(v.z, 4) + ")";
}

}  // namespace

auto stackVerdict(const sim::World& world, std::string_view upper, std::string_view lower)
    -> StackVerdict {
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

auto sceneReport(const sim::World& world) -> SceneReport {
  SceneReport report;
  report.time = world.time();
  for (const char* name : kBlocks) {
    if (auto pose = sim::bodyPose(world, name)) report.blocks.push_back({name, pose->position});
  }
  if (report.blocks.size() == 2) {
    const bool firstHigher = report.blocks[0].centre.z > report.blocks[1].centre.z;
    const BlockReport& upper = report.blocks[firstHigher ? 0 : 1];
    const BlockReport& lower = report.blocks[firstHigher ? 1 : 0];
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
