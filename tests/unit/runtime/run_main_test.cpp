// runMain(): flags, exit codes, the trace file; and the construction code a generated
// program emits (the example in stdlib/runtime/README.md).
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "helpers.h"

namespace rt = smachac::runtime;

namespace {

/// What `smachac -target=cpp` emits for a small script, minus main()'s signature.
int generatedMain(int argc, char** argv) {
  rt::StateMachine sm({.outcomes = {"succeeded", "aborted"}, .userdata = {{"n", 0}}});
  sm.add("INC",
         std::make_unique<rt::CallbacksState>(
             rt::StateSpec{.input_keys = {"n"}},
             rt::Callbacks{
                 {"n", [](rt::UserData& ud) -> rt::Value { return ud.get<int64_t>("n") + 1; }}}),
         {{"succeeded", "CHECK"}});
  sm.add(
      "CHECK",
      std::make_unique<rt::ConditionalOutcomeState>(
          rt::StateSpec{.outcomes = {"done"}, .input_keys = {"n"}},
          rt::Callbacks{
              {"done", [](rt::UserData& ud) -> rt::Value { return ud.get<int64_t>("n") >= 3; }}}),
      {{"done", "PAR"}, {"default", "INC"}});
  auto& par =
      sm.add("PAR",
             std::make_unique<rt::Concurrence>(rt::ConcurrenceSpec{
                 .outcomes = {"succeeded", "aborted"},
                 .default_outcome = "aborted",
                 .outcome_map = {{"succeeded", {{"LEFT", "succeeded"}, {"RIGHT", "succeeded"}}}}}),
             {{"succeeded", "succeeded"}, {"aborted", "aborted"}});
  par.add("LEFT", std::make_unique<rt::SleepState>(0.01));
  par.add("RIGHT", std::make_unique<rt::SleepState>(0.02));
  return rt::runMain(sm, argc, argv);
}

int callMain(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  return generatedMain(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("a generated program runs and writes its trace file") {
  std::string path = "smachac_runtime_trace_test.jsonl";
  CHECK(callMain({"machine", "--quiet", "--seed=3", "--trace-file=" + path}) == 0);
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  std::remove(path.c_str());
  CHECK(text.str().find("\"event\":\"transition\",\"state\":\"CHECK\",\"outcome\":\"default\","
                        "\"target\":\"INC\"") != std::string::npos);
  CHECK(text.str().find("\"event\":\"exit\",\"state\":\"PAR/RIGHT\",\"outcome\":\"succeeded\"") !=
        std::string::npos);
  CHECK(
      text.str().ends_with("\"event\":\"exit\",\"state\":\"\",\"outcome\":\"succeeded\","
                           "\"written\":[]}\n"));
}

TEST_CASE("bad flags are usage errors") {
  CHECK(callMain({"machine", "--bogus"}) == 2);
  CHECK(callMain({"machine", "--trace=xml"}) == 2);
  CHECK(callMain({"machine", "--seed=x1"}) == 2);
  CHECK(callMain({"machine", "--trace-file=/nonexistent/dir/trace"}) == 2);
}

TEST_CASE("--help documents every flag and exits with 0 without running the machine") {
  std::stringstream captured;
  std::streambuf* previous = std::cout.rdbuf(captured.rdbuf());
  int status = callMain({"machine", "--help"});
  std::cout.rdbuf(previous);
  CHECK(status == 0);
  const std::string help = captured.str();
  CHECK(
      help.starts_with("usage: machine [--trace=json|log] [--trace-file=PATH] [--seed=N] "
                       "[--quiet] [--print-userdata] [--help]\n"));
  for (const char* flag : {"--trace=json|log  ", "--trace-file=PATH  ", "--seed=N  ", "--quiet  ",
                           "--print-userdata  ", "-h, --help  ", "SIGINT", "Exit status"}) {
    CHECK_MESSAGE(help.find(flag) != std::string::npos, flag);
  }
  CHECK(help.find("outcome: succeeded") == std::string::npos);  // the machine did not run
}

TEST_CASE("a failing machine exits with 1") {
  rt::StateMachine sm({.outcomes = {"done"}});
  sm.add("A", rt::testing::returns("other", {"other"}));
  std::string name = "machine";
  std::string quiet = "--quiet";
  char* argv[] = {name.data(), quiet.data()};
  CHECK(rt::runMain(sm, 2, argv) == 1);
}
