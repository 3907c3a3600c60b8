// The Baxter state classes one at a time: userdata formats, variables versus input keys,
// IK, moves and their preemption, the gripper's grasp check, model loading, the robot flags
// and the scene report.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <thread>

#include "robot_machines.h"
#include "smachac/sim/bodies.h"
#include "smachac/sim/ik.h"
#include "smachac/sim/standard_poses.h"

namespace smachac::robot::test {
namespace {

const rt::List kGripperDown = {-0.02496, 0.99965, 0.00738, 0.00486};

// A machine around one state: the state's outcomes end the machine.
std::unique_ptr<rt::StateMachine> wrap(std::unique_ptr<rt::State> state, rt::Map userdata = {},
                                       rt::Remapping remapping = {}) {
  auto sm = std::make_unique<rt::StateMachine>(rt::StateMachineSpec{
      .outcomes = {"succeeded", "aborted", "preempted"}, .userdata = std::move(userdata)});
  sm->add("STATE", std::move(state), {}, std::move(remapping));
  return sm;
}

std::string outcomeOf(rt::StateMachine& sm) {
  const rt::RunResult result = rt::run(sm);
  INFO(result.error);
  REQUIRE(result.ok());
  return result.outcome;
}

rt::Value joints(const sim::JointPositions& q) { return jointsValue(q); }

double maxError(const sim::JointPositions& a, const sim::JointPositions& b) {
  double error = 0.0;
  for (size_t i = 0; i < a.size(); ++i) error = std::max(error, std::abs(a[i] - b[i]));
  return error;
}

TEST_SUITE("sim_robot_states") {
  TEST_CASE("poses, offsets and joint positions in both shapes") {
    const sim::Pose nested = parsePose(rt::List{rt::List{0.7, 0.15, -0.129}, kGripperDown});
    const sim::Pose flat =
        parsePose(rt::List{0.7, 0.15, -0.129, -0.02496, 0.99965, 0.00738, 0.00486});
    CHECK(nested.position.z == doctest::Approx(-0.129));
    CHECK(flat.orientation.y == doctest::Approx(nested.orientation.y));
    const sim::Quaternion& q = nested.orientation;
    CHECK(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z == doctest::Approx(1.0));
    const sim::Pose hover =
        applyOffset(nested, parseOffset(rt::List{rt::List{0.0, 0.0, 0.15}, rt::List{0, 0, 0, 0}}));
    CHECK(hover.position.z == doctest::Approx(0.021));
    CHECK(hover.orientation.y == doctest::Approx(nested.orientation.y));
    CHECK(parseOffset(rt::List{0.0, 0.1, 0.0}).position.y == doctest::Approx(0.1));
    const rt::List untuck = {-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5};
    CHECK(parseJointPositions(untuck)[3] == doctest::Approx(1.94));
    CHECK(parseJointPositions(rt::List{untuck})[6] == doctest::Approx(-0.5));
    CHECK(parsePose(poseValue(nested)).position.x == doctest::Approx(0.7));
    CHECK_THROWS_WITH_AS(parsePose(rt::List{1, 2, 3}),
                         doctest::Contains("a pose must be [[x, y, z], [qx, qy, qz, qw]]"),
                         FormatError);
    CHECK_THROWS_AS(parsePose(rt::List{rt::List{0, 0, 0}, rt::List{0, 0, 0, 0}}), FormatError);
    CHECK_THROWS_AS(parseJointPositions(rt::List{1, 2, 3}), FormatError);
    CHECK_THROWS_AS(parseLimb("middle"), FormatError);
    CHECK(parseFrame("base") == sim::Frame::Base);
  }

  TEST_CASE("IK writes joints that reach the pose plus offset; out of reach aborts") {
    auto robot = makeRobot();
    auto sm = wrap(std::make_unique<PoseToJointTrajServiceState>(
                       *robot, PoseToJointTrajServiceArgs{.limb = "left"}),
                   {{"pick_pose", rt::List{rt::List{0.7, 0.15, -0.129}, kGripperDown}},
                    {"hover", rt::List{0.0, 0.0, 0.15}}},
                   {{"poses", "pick_pose"}, {"offsets", "hover"}, {"joints", "hover_joints"}});
    CHECK(outcomeOf(*sm) == "succeeded");
    sim::Ik ik(robot->world());
    const auto q = parseJointPositions(sm->userdata().at("hover_joints"));
    const sim::Pose reached =
        robot->world().fromWorld(ik.forward(sim::Side::Left, q), sim::Frame::Base);
    CHECK(reached.position.z == doctest::Approx(0.021).epsilon(1e-3));
    sm->userdata().set("pick_pose", rt::List{rt::List{1.6, 0.15, -0.129}, kGripperDown});
    sm->userdata().set("hover_joints", nullptr);
    CHECK(outcomeOf(*sm) == "aborted");
    CHECK(sm->userdata().at("hover_joints").isNull());
  }

  TEST_CASE("a move reaches its goal; the limb can come from userdata") {
    auto robot = makeRobot();
    auto sm = wrap(std::make_unique<MoveToJointPositionsState>(*robot),
                   {{"limb", "right"}, {"positions", joints(sim::neutralPose(sim::Side::Right))}});
    CHECK(outcomeOf(*sm) == "succeeded");
    const auto q = robot->world().limb(sim::Side::Right).jointPositions();
    CHECK(maxError(q, sim::neutralPose(sim::Side::Right)) < 0.01);
  }

  TEST_CASE("a preempted move stops early, holding the arm") {
    auto robot = makeRobot();
    auto sm = wrap(std::make_unique<MoveToJointPositionsState>(
        *robot, MoveToJointPositionsArgs{.limb = "left",
                                         .positions = joints(sim::tuckPose(sim::Side::Left))}));
    double requested = 0.0;  // simulated time just after the request
    // The preempter steps the world in lockstep with the move (as a robot state does), so the
    // request comes at 0.5 s of simulated time however the OS schedules the two threads: the
    // move cannot step on until the preempter has asked and stopped taking part.
    robot->beginExecution();
    std::thread preempter([&] {
      robot->stepUntil([&] { return robot->world().time() >= 0.5; }, 10.0);
      sm->requestPreempt();
      requested = robot->world().time();
      robot->endExecution();
    });
    CHECK(outcomeOf(*sm) == "preempted");
    preempter.join();
    CHECK(robot->world().time() <= requested + 0.01);
    const auto held = robot->world().limb(sim::Side::Left).jointPositions();
    robot->world().stepFor(0.5);
    CHECK(maxError(held, robot->world().limb(sim::Side::Left).jointPositions()) < 0.05);
  }

  TEST_CASE("a trajectory visits its waypoints in order") {
    auto robot = makeRobot();
    const rt::List points = {joints(sim::neutralPose(sim::Side::Left)),
                             joints(sim::untuckPose(sim::Side::Left))};
    auto sm = wrap(std::make_unique<FollowJointTrajActionState>(
        *robot, FollowJointTrajActionArgs{.limb = "left", .points = points}));
    CHECK(outcomeOf(*sm) == "succeeded");
    const auto q = robot->world().limb(sim::Side::Left).jointPositions();
    CHECK(maxError(q, sim::untuckPose(sim::Side::Left)) < 0.01);
  }

  TEST_CASE("the endpoint pose is read into userdata") {
    auto robot = makeRobot();
    auto sm =
        wrap(std::make_unique<ReadEndpointPoseState>(*robot, ReadEndpointPoseArgs{.limb = "left"}),
             {}, {{"pose", "endpoint"}});
    CHECK(outcomeOf(*sm) == "succeeded");
    const sim::Pose read = parsePose(sm->userdata().at("endpoint"));
    const sim::Pose actual = robot->world().limb(sim::Side::Left).endpointPose();
    CHECK(read.position.x == doctest::Approx(actual.position.x));
    CHECK(read.orientation.w == doctest::Approx(actual.orientation.w));
  }

  TEST_CASE("closing on nothing aborts unless no grasp is expected") {
    auto robot = makeRobot();
    auto expecting = wrap(std::make_unique<GripperInterfaceState>(
        *robot, GripperInterfaceArgs{.limb = "left", .command = "close"}));
    CHECK(outcomeOf(*expecting) == "aborted");
    auto empty = wrap(std::make_unique<GripperInterfaceState>(
        *robot, GripperInterfaceArgs{.limb = "left", .command = "close", .expect_grasp = false}));
    CHECK(outcomeOf(*empty) == "succeeded");
    auto open = wrap(std::make_unique<GripperInterfaceState>(*robot),
                     {{"limb", "left"}, {"command", "open"}});
    CHECK(outcomeOf(*open) == "succeeded");
  }

  TEST_CASE("models load at a pose in a frame; an unknown model is a script error") {
    auto robot = makeRobot();
    auto sm = wrap(
        std::make_unique<LoadModelState>(*robot, LoadModelArgs{.model_name = "block2",
                                                               .pose = rt::List{0.6, -0.1, -0.13},
                                                               .reference_frame = "base"}));
    CHECK(outcomeOf(*sm) == "succeeded");
    CHECK(sim::bodyPose(robot->world(), "block2")->position.y == doctest::Approx(-0.1));
    auto unknown = wrap(
        std::make_unique<LoadGazeboModelState>(*robot, LoadGazeboModelArgs{.model_name = "block9"}),
        {{"pose", rt::List{0.6, -0.1, 0.8}}});
    const rt::RunResult result = rt::run(*unknown);
    CHECK(result.outcome == "aborted");
    CHECK(result.error.find("the scene has no model `block9`") != std::string::npos);
  }

  TEST_CASE("the robot flags are taken out of argv") {
    std::string args[] = {"prog",        "--trace=log", "--snapshots=/tmp/x", "--start-pose=untuck",
                          "--no-report", "--quiet"};
    char* argv[] = {args[0].data(), args[1].data(), args[2].data(), args[3].data(),
                    args[4].data(), args[5].data(), nullptr};
    int argc = 6;
    RobotOptions options;
    CHECK_FALSE(takeRobotFlags(argc, argv, options).has_value());
    CHECK(argc == 3);
    CHECK(std::string(argv[1]) == "--trace=log");
    CHECK(std::string(argv[2]) == "--quiet");
    CHECK(options.snapshot_dir == "/tmp/x");
    CHECK(options.start_pose == StartPose::Untuck);
    CHECK_FALSE(options.report);
  }

  TEST_CASE("the report judges a stack with the tests' thresholds") {
    auto robot = makeRobot();
    REQUIRE(sim::placeBody(robot->world(), "block1", {{0.7, 0.0, -0.13}, {}}) ==
            sim::PlaceStatus::Placed);
    REQUIRE(sim::placeBody(robot->world(), "block2", {{0.705, 0.0, -0.079}, {}}) ==
            sim::PlaceStatus::Placed);
    robot->world().stepFor(1.0);
    const SceneReport report = sceneReport(robot->world());
    CHECK(report.stack.stacked);
    CHECK(report.stack.upper == "block2");
    std::ostringstream text;
    printReport(text, report);
    CHECK(text.str().find("stacked: block2 on block1") != std::string::npos);
    CHECK_FALSE(stackVerdict(robot->world(), "block1", "block2").stacked);
  }
}

}  // namespace
}  // namespace smachac::robot::test
