// Shared fixtures of the physical simulation tests: the scene of the paper's experiments
// (sim/models/scene.xml: table, 5 cm blocks, demo poses in the base frame) and small geometric
// helpers.
#pragma once

#include <memory>

#include "smachac/sim/types.h"
#include "smachac/sim/world.h"

namespace smachac::sim::test {

inline constexpr double kBlockSize = 0.05;
inline constexpr double kTableTopZ = -0.155;  // base frame
inline constexpr double kBlockRestZ = kTableTopZ + kBlockSize / 2;
inline constexpr double kHoverOffset = 0.15;
/// The demo's TCP targets (base frame): block pose 1 and block pose 2.
inline constexpr Vec3 kPose1{0.7, 0.15, -0.129};
inline constexpr Vec3 kPose2{0.75, 0.0, -0.129};

/// Loads sim/models/scene.xml; fails the test when it cannot.
std::unique_ptr<World> loadWorld();

/// TCP pose over a point with the demo's overhead gripper orientation (base frame).
Pose gripPose(const Vec3& tcp);
/// The TCP grip pose for a block resting with its centre at `centre`: 1 mm above the centre,
/// as in the demo (block centre -0.130, TCP target -0.129).
Pose gripPoseForBlock(const Vec3& centre);
/// Puts a block on the table (centre at rest height) with its TCP target at `tcp`'s x, y.
void putBlockOnTable(World& world, const char* name, const Vec3& tcp);

/// Largest |a[i] - b[i]| over the joints.
double maxJointError(const JointPositions& a, const JointPositions& b);
double distance(const Vec3& a, const Vec3& b);
double horizontalDistance(const Vec3& a, const Vec3& b);
/// Centre of a body (base frame); fails the test for an unknown body.
Vec3 centreOf(const World& world, const char* name);

}  // namespace smachac::sim::test
