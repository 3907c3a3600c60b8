// The paper's three experiments run physically: each machine is built as the generated C++
// builds it from examples/baxter/*.yml (robot_machines.cpp), run on the runtime in MuJoCo,
// and judged by where the blocks end up, one second after the last release.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "robot_machines.h"
#include "smachac/sim/bodies.h"
#include "smachac/sim/gripper.h"

namespace smachac::robot::test {
namespace {

rt::RunResult runMachine(rt::StateMachine& sm) {
  rt::RunResult result = rt::run(sm);
  INFO(result.error);
  REQUIRE(result.ok());
  return result;
}

void checkNoWarnings(const SceneReport& report) {
  for (const sim::WarningCount& warning : report.warnings) {
    FAIL_CHECK(warning.name << " raised " << warning.count << " times");
  }
}

void checkStacked(const SceneReport& report, const char* upper, const char* lower) {
  INFO("|dxy| " << report.stack.horizontal << " m, |dz - size| " << report.stack.height_error);
  CHECK(report.stack.upper == upper);
  CHECK(report.stack.lower == lower);
  CHECK(report.stack.stacked);
}

double distance(const sim::Vec3& a, const sim::Vec3& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

// When (simulated seconds) each state was entered and left.
class SimTimeSink : public rt::TraceSink {
 public:
  explicit SimTimeSink(const sim::World& world) : world_(world) {}
  void write(const rt::TraceEvent& event) override {
    if (event.kind != rt::TraceKind::Enter && event.kind != rt::TraceKind::Exit) return;
    const double now = world_.time();
    std::lock_guard lock(mutex_);
    auto& [start, end] = intervals_[std::string(event.state)];
    (event.kind == rt::TraceKind::Enter ? start : end) = now;
  }
  std::pair<double, double> interval(const std::string& state) {
    std::lock_guard lock(mutex_);
    return intervals_.at(state);
  }

 private:
  const sim::World& world_;
  std::mutex mutex_;
  std::map<std::string, std::pair<double, double>> intervals_;
};

// Calls `action` when the state at `path` is entered, on the machine's thread.
class EnterHook : public rt::TraceSink {
 public:
  EnterHook(std::string path, std::function<void()> action)
      : path_(std::move(path)), action_(std::move(action)) {}
  void write(const rt::TraceEvent& event) override {
    if (event.kind != rt::TraceKind::Enter || event.state != path_) return;
    fired_ = true;
    action_();
  }
  /// Whether the state was entered (read once the machine has returned).
  bool fired() const { return fired_; }

 private:
  bool fired_ = false;
  std::string path_;
  std::function<void()> action_;
};

// Index of the first trace line equal to `line` (lines() is "enter X", "exit X outcome", ...).
std::ptrdiff_t lineIndex(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) - lines.begin();
}

TEST_SUITE("sim_robot_pick_and_place") {
  TEST_CASE("pick_and_place.yml puts the block within 1 cm of its place pose") {
    const auto dir = std::filesystem::temp_directory_path() / "smachac_robot_pick_and_place";
    std::filesystem::remove_all(dir);
    auto robot = makeRobot({.snapshot_dir = dir.string()});
    auto sm = buildPickAndPlace(*robot);
    auto trace = std::make_shared<rt::RecordingSink>();
    sm->setTraceSink(trace);
    CHECK(runMachine(*sm).outcome == "succeeded");
    const SceneReport report = finishBaxter(*robot);
    const sim::Vec3 placed = sim::bodyPose(robot->world(), "block1")->position;
    INFO("block1 at " << placed.x << " " << placed.y << " " << placed.z);
    CHECK(distance(placed, {0.75, 0.0, -0.13}) < 0.01);
    CHECK_FALSE(robot->world().gripper(sim::Side::Left).heldBody().has_value());
    checkNoWarnings(report);
    const auto lines = trace->lines();
    CHECK(lineIndex(lines, "exit PICK_BLOCK/CLOSE_GRIPPER succeeded") <
          lineIndex(lines, "exit PLACE_BLOCK/OPEN_GRIPPER succeeded"));
    // Gripper actions and the end: 4 snapshots.
    const auto snapshots = robot->snapshots();
    CHECK(snapshots.size() == 4);
    for (const std::string& png : snapshots) CHECK(std::filesystem::file_size(png) > 1000);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a block out of reach ends the machine in aborted, at the first IK") {
    auto robot = makeRobot();
    auto sm = buildPickAndPlace(*robot);
    sm->userdata().set("block_model_pose_base",
                       rt::List{rt::List{1.4, 0.15, -0.13}, rt::List{0.0, 0.0, 0.0, 1.0}});
    sm->userdata().set(
        "block_model_pick_pose",
        rt::List{rt::List{1.4, 0.15, -0.129}, rt::List{-0.02496, 0.99965, 0.00738, 0.00486}});
    CHECK(runMachine(*sm).outcome == "aborted");
    const auto messages = robot->messages();
    REQUIRE(messages.size() == 1);
    CHECK(messages[0].find("PICK_BLOCK/IK_PICK_BLOCK_HOVER_POSE: no IK solution") !=
          std::string::npos);
    checkNoWarnings(sceneReport(robot->world()));
  }

  TEST_CASE("a generated main(): setUpBaxter, the machine, runBaxter and its report") {
    std::string args[] = {"pick_and_place", "--robot-quiet", "--start-pose=neutral", "--quiet"};
    char* argv[] = {args[0].data(), args[1].data(), args[2].data(), args[3].data(), nullptr};
    int argc = 4;
    auto robot = setUpBaxter(argc, argv);
    REQUIRE(robot != nullptr);
    CHECK(argc == 2);  // --quiet is runMain's
    auto sm = buildPickAndPlace(*robot);
    sm->userdata().set(
        "block_model_pick_pose",
        rt::List{rt::List{1.4, 0.15, -0.129}, rt::List{-0.02496, 0.99965, 0.00738, 0.00486}});
    std::ostringstream out;
    std::streambuf* saved = std::cout.rdbuf(out.rdbuf());
    const int code = runBaxter(*sm, *robot, argc, argv);
    std::cout.rdbuf(saved);
    CHECK(code == 0);
    CHECK(out.str().find("block1 at (0.7") != std::string::npos);
    CHECK(out.str().find("not stacked: block1 on block2") != std::string::npos);
  }
}

TEST_SUITE("sim_robot_stacking") {
  TEST_CASE("stacking.yml leaves block 2 resting on block 1") {
    auto robot = makeRobot();
    auto sm = buildStacking(*robot);
    CHECK(runMachine(*sm).outcome == "succeeded");
    const SceneReport report = finishBaxter(*robot);
    checkStacked(report, "block2", "block1");
    CHECK(distance(report.blocks[0].centre, {0.75, 0.0, -0.13}) < 0.01);
    checkNoWarnings(report);
  }
}

TEST_SUITE("sim_robot_dual_arm") {
  TEST_CASE("dual_arm_stacking.yml: both arms pick at once, then block 2 rests on block 1") {
    auto robot = makeRobot();
    auto sm = buildDualArmStacking(*robot);
    auto times = std::make_shared<SimTimeSink>(robot->world());
    sm->setTraceSink(times);
    sm->setThreadObserver(robot.get());  // as runBaxter does
    CHECK(runMachine(*sm).outcome == "succeeded");
    const SceneReport report = finishBaxter(*robot);
    checkStacked(report, "block2", "block1");
    checkNoWarnings(report);
    // The picks ran at once in simulated time: simulated time waits for both of the
    // Concurrence's threads from its split, however late the OS starts the second one, so
    // both picks start at the same simulated time and the shorter lies within the longer.
    // Plain names, not structured bindings: doctest's INFO captures them in a lambda.
    const std::pair<double, double> pick1 = times->interval("PICK_BLOCKS/PICK_BLOCK_1");
    const std::pair<double, double> pick2 = times->interval("PICK_BLOCKS/PICK_BLOCK_2");
    const double start1 = pick1.first, end1 = pick1.second;
    const double start2 = pick2.first, end2 = pick2.second;
    INFO("PICK_BLOCK_1 " << start1 << " to " << end1 << " s, PICK_BLOCK_2 " << start2 << " to "
                         << end2 << " s");
    CHECK(std::abs(start1 - start2) < 0.01);
    const double overlap = std::min(end1, end2) - std::max(start1, start2);
    CHECK(overlap > 0.95 * std::min(end1 - start1, end2 - start2));
  }

  TEST_CASE("preempting the dual-arm machine stops both arms in PICK_BLOCKS") {
    auto robot = makeRobot();
    auto sm = buildDualArmStacking(*robot);
    auto trace = std::make_shared<rt::RecordingSink>();
    // The preempter takes part in the lockstep from PICK_BLOCKS' entry (registered on the
    // machine's thread, before the arms can step), so the request comes 0.5 s of simulated time
    // into the picks however the OS schedules the threads.
    std::promise<double> entered;  // the simulated time PICK_BLOCKS was entered
    auto on_pick = std::make_shared<EnterHook>("PICK_BLOCKS", [&] {
      robot->beginExecution();
      entered.set_value(robot->world().time());
    });
    sm->setTraceSink(
        std::make_shared<rt::TeeSink>(std::vector<std::shared_ptr<rt::TraceSink>>{trace, on_pick}));
    double entry_time = 0.0, requested = 0.0;  // simulated times of the entry and the request
    std::thread preempter([&, entry = entered.get_future()]() mutable {
      entry_time = entry.get();
      if (entry_time < 0) return;  // the machine ended without entering PICK_BLOCKS
      robot->stepUntil([&] { return robot->world().time() >= entry_time + 0.5; }, 10.0);
      sm->requestPreempt();
      requested = robot->world().time();
      robot->endExecution();
    });
    const rt::RunResult result = rt::run(*sm);
    if (!on_pick->fired()) entered.set_value(-1.0);
    preempter.join();
    INFO(result.error);
    REQUIRE(result.ok());
    CHECK(result.outcome == "preempted");
    INFO("PICK_BLOCKS entered at " << entry_time << " s, preempted at " << requested << " s");
    CHECK(requested >= entry_time + 0.5);
    CHECK(requested < entry_time + 0.52);
    CHECK(robot->world().time() <= requested + 0.02);
    const auto lines = trace->lines();
    CHECK(lineIndex(lines, "exit PICK_BLOCKS preempted") < std::ssize(lines));
  }
}

}  // namespace
}  // namespace smachac::robot::test
