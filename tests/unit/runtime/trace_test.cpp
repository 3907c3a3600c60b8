// Trace: the order and contents of events, their JSON and readable forms.
#include <doctest/doctest.h>

#include <sstream>
#include <stdexcept>

#include "helpers.h"

namespace rt = smachac::runtime;
using rt::LambdaState;
using rt::StateMachine;
using rt::StateSpec;
using rt::UserData;
using rt::testing::returns;

namespace {

std::unique_ptr<StateMachine> twoStep() {
  auto sm = std::make_unique<StateMachine>(rt::StateMachineSpec{.outcomes = {"done"}});
  auto& sub =
      sm->add("SUB", std::make_unique<StateMachine>(rt::StateMachineSpec{.outcomes = {"ok"}}),
              {{"ok", "WRITE"}});
  sub.add("INNER", returns("ok"));
  sm->add(
      "WRITE",
      std::make_unique<LambdaState>(StateSpec{.outcomes = {"written"}, .output_keys = {"x", "y"}},
                                    [](UserData& ud) {
                                      ud.set("y", 1);
                                      ud.set("x", "a\"b");
                                      ud.set("y", 2);
                                      return "written";
                                    }),
      {{"written", "done"}}, {{"x", "parent_x"}});
  return sm;
}

}  // namespace

TEST_CASE("events come in execution order with outcomes, targets and written keys") {
  auto sm = twoStep();
  auto sink = std::make_shared<rt::RecordingSink>();
  sm->setTraceSink(sink);
  REQUIRE(rt::run(*sm).ok());
  CHECK(sink->lines() == std::vector<std::string>{
                             "enter ",
                             "enter SUB",
                             "enter SUB/INNER",
                             "exit SUB/INNER ok",
                             "transition SUB/INNER ok ok",
                             "exit SUB ok",
                             "transition SUB ok WRITE",
                             "enter WRITE",
                             "exit WRITE written",
                             "transition WRITE written done",
                             "exit  done",
                         });
  auto records = sink->records();
  CHECK(records[4].terminal);
  CHECK_FALSE(records[6].terminal);
  CHECK(records[8].written == std::vector<std::string>{"y", "parent_x"});
  for (std::size_t i = 1; i < records.size(); ++i) CHECK(records[i].t_us >= records[i - 1].t_us);
}

TEST_CASE("a sink attached again after untraced runs sees each run's written keys") {
  auto sm = twoStep();
  sm->setTraceSink(std::make_shared<rt::RecordingSink>());
  REQUIRE(rt::run(*sm).ok());
  sm->setTraceSink(nullptr);
  REQUIRE(rt::run(*sm).ok());
  auto sink = std::make_shared<rt::RecordingSink>();
  sm->setTraceSink(sink);
  REQUIRE(rt::run(*sm).ok());
  auto records = sink->records();
  REQUIRE(records.size() == 11);
  CHECK(records[8].written == std::vector<std::string>{"y", "parent_x"});
}

TEST_CASE("a state added after the sink is attached is traced too") {
  StateMachine sm({.outcomes = {"done"}});
  auto sink = std::make_shared<rt::RecordingSink>();
  sm.setTraceSink(sink);
  sm.add("LATE", returns("done"));
  REQUIRE(rt::run(sm).ok());
  CHECK(sink->lines().at(1) == "enter LATE");
}

TEST_CASE("JSON lines") {
  auto sm = twoStep();
  std::ostringstream out;
  sm->setTraceSink(std::make_shared<rt::JsonLinesSink>(out));
  REQUIRE(rt::run(*sm).ok());
  std::istringstream lines(out.str());
  std::vector<std::string> all;
  for (std::string line; std::getline(lines, line);) {
    // Drop the time, which varies.
    REQUIRE(line.starts_with("{\"t_us\":"));
    all.push_back(line.substr(line.find(',') + 1));
  }
  REQUIRE(all.size() == 11);
  CHECK(all[0] == "\"event\":\"enter\",\"state\":\"\"}");
  CHECK(all[4] ==
        "\"event\":\"transition\",\"state\":\"SUB/INNER\",\"outcome\":\"ok\",\"target\":\"ok\","
        "\"terminal\":true}");
  CHECK(all[8] ==
        "\"event\":\"exit\",\"state\":\"WRITE\",\"outcome\":\"written\",\"written\":[\"y\","
        "\"parent_x\"]}");
}

TEST_CASE("readable lines and error events") {
  StateMachine sm({.outcomes = {"done"}});
  sm.add("BAD", std::make_unique<LambdaState>(
                    StateSpec{.outcomes = {"done"}},
                    [](UserData&) -> std::string { throw std::runtime_error("line\nbreak"); }));
  std::ostringstream log;
  std::ostringstream json;
  sm.setTraceSink(std::make_shared<rt::TeeSink>(std::vector<std::shared_ptr<rt::TraceSink>>{
      std::make_shared<rt::LogSink>(log), std::make_shared<rt::JsonLinesSink>(json)}));
  CHECK(rt::run(sm).error == "state `BAD` failed: line\nbreak");
  CHECK(log.str().find("] enter <root>\n") != std::string::npos);
  CHECK(log.str().find("] error BAD: state `BAD` failed: line\nbreak\n") != std::string::npos);
  CHECK(json.str().find("\"event\":\"error\",\"state\":\"BAD\",\"message\":\"state `BAD` failed: "
                        "line\\nbreak\"}") != std::string::npos);
}

TEST_CASE("formatted lines for each kind") {
  std::vector<std::string> written{"a", "b"};
  rt::TraceEvent exit{
      .kind = rt::TraceKind::Exit, .state = "SM/X", .outcome = "ok", .written = &written};
  CHECK(rt::formatLogLine(exit, 1500000) == "[    1.500000] exit SM/X -> ok (wrote a, b)");
  rt::TraceEvent transition{.kind = rt::TraceKind::Transition,
                            .state = "X",
                            .outcome = "ok",
                            .target = "done",
                            .terminal = true};
  CHECK(rt::formatLogLine(transition, 0) ==
        "[    0.000000] transition X --ok--> done (container outcome)");
  rt::TraceEvent preempt{.kind = rt::TraceKind::Preempt, .state = "X"};
  CHECK(rt::formatJsonLine(preempt, 7) == "{\"t_us\":7,\"event\":\"preempt\",\"state\":\"X\"}");
}
