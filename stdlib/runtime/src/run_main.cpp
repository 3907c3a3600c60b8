// runMain(): the flags of a generated program, its trace sinks, and SIGINT/SIGTERM turned into
// a preempt request by a watcher thread (signals are blocked in the machine's threads and
// taken with sigtimedwait, so no handler runs in signal context).
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "smachac/runtime/container.h"
#include "smachac/runtime/core_states.h"
#include "smachac/runtime/run.h"
#include "smachac/runtime/trace.h"

namespace smachac::runtime {

namespace {

struct Options {
  std::string trace;       ///< "", "json" or "log"
  std::string trace_file;  ///< JSON lines written here when set
  std::optional<uint64_t> seed;
  bool quiet = false;
  bool print_userdata = false;
  bool help = false;
};

constexpr std::string_view kUsage =
    " [--trace=json|log] [--trace-file=PATH] [--seed=N] [--quiet] [--print-userdata] [--help]\n";

constexpr std::string_view kHelp =
    R"(Runs the state machine this program was generated from and prints its outcome.

  --trace=json|log    trace every state entered and left, each transition and preempt
                      request on standard error, as JSON lines or readable lines
                      (also from the environment: SMACHAC_TRACE=json|log)
  --trace-file=PATH   also write the trace to PATH, as JSON lines
  --seed=N            seed RandomOutcomeState's choices: one seed gives the same choices
                      on every machine
  --quiet             do not print `outcome: <outcome>`
  --print-userdata    print the top machine's final userdata, as a Python dict
  -h, --help          print this help

The first SIGINT or SIGTERM asks the machine to preempt, by SMACH's rules: the running
state decides whether it stops; a second one ends the program at once.
Exit status: 0 when the machine returned an outcome, 1 when a state failed, 2 on a bad
flag or an unwritable trace file.
)";

/// Parses the flags; returns an error message on a bad one.
std::optional<std::string> parseFlags(int argc, char** argv, Options& options) {
  if (const char* env = std::getenv("SMACHAC_TRACE")) options.trace = env;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg.starts_with("--trace=")) {
      options.trace = arg.substr(8);
    } else if (arg.starts_with("--trace-file=")) {
      options.trace_file = arg.substr(13);
    } else if (arg.starts_with("--seed=")) {
      char* end = nullptr;
      std::string digits(arg.substr(7));
      options.seed = std::strtoull(digits.c_str(), &end, 10);
      if (digits.empty() || *end != '\0') return "bad seed `" + digits + "`";
    } else if (arg == "--quiet") {
      options.quiet = true;
    } else if (arg == "--print-userdata") {
      options.print_userdata = true;
    } else if (arg == "--help" || arg == "-h") {
      options.help = true;
    } else {
      return "unknown flag `" + std::string(arg) + "`";
    }
  }
  if (!options.trace.empty() && options.trace != "json" && options.trace != "log") {
    return "unknown trace format `" + options.trace + "` (expected json or log)";
  }
  return std::nullopt;
}

/// JSON lines into a file it owns.
class JsonFileSink : public TraceSink {
 public:
  explicit JsonFileSink(const std::string& path) : file_(path), lines_(file_) {}
  bool ok() const { return file_.good(); }
  void write(const TraceEvent& event) override { lines_.write(event); }

 private:
  std::ofstream file_;
  JsonLinesSink lines_;
};

/// While alive, the first SIGINT/SIGTERM preempts `root`; a second ends the process.
class SignalPreempter {
 public:
  explicit SignalPreempter(State& root) : root_(root) {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    sigaddset(&signals_, wakeSignal());
    pthread_sigmask(SIG_BLOCK, &signals_, &old_mask_);
    thread_ = std::thread([this] { watch(); });
  }
  ~SignalPreempter() {
    // Woken at once: a program ends when its machine does, not at the watcher's next timeout.
    stop_.store(true);
    pthread_kill(thread_.native_handle(), wakeSignal());
    thread_.join();
    pthread_sigmask(SIG_SETMASK, &old_mask_, nullptr);
  }
  SignalPreempter(const SignalPreempter&) = delete;
  SignalPreempter& operator=(const SignalPreempter&) = delete;

 private:
  /// Sent by the destructor to the watcher thread only.
  static int wakeSignal() { return SIGRTMIN; }

  void watch() {
    int received = 0;
    while (!stop_.load()) {
      timespec timeout{.tv_sec = 1, .tv_nsec = 0};
      int signal = sigtimedwait(&signals_, nullptr, &timeout);
      if (signal <= 0 || signal == wakeSignal()) continue;
      if (++received > 1) std::_Exit(128 + signal);
      std::cerr << "interrupted: preempting the machine (again to quit)\n";
      root_.requestPreempt();
    }
  }

  State& root_;
  sigset_t signals_{};
  sigset_t old_mask_{};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// The sinks the flags ask for; false when the trace file cannot be opened.
bool attachSinks(State& root, const Options& options) {
  std::vector<std::shared_ptr<TraceSink>> sinks;
  if (options.trace == "json") sinks.push_back(std::make_shared<JsonLinesSink>(std::cerr));
  if (options.trace == "log") sinks.push_back(std::make_shared<LogSink>(std::cerr));
  if (!options.trace_file.empty()) {
    auto file = std::make_shared<JsonFileSink>(options.trace_file);
    if (!file->ok()) return false;
    sinks.push_back(std::move(file));
  }
  if (sinks.size() == 1) root.setTraceSink(sinks.front());
  if (sinks.size() > 1) root.setTraceSink(std::make_shared<TeeSink>(std::move(sinks)));
  return true;
}

/// The top container's userdata in Python's spelling (a dict), `{}` for a leaf.
std::string finalUserdata(const State& root) {
  const auto* container = dynamic_cast<const Container*>(&root);
  return Value(container != nullptr ? container->userdata().snapshot() : Map{}).repr();
}

}  // namespace

int runMain(State& root, int argc, char** argv) {
  Options options;
  const char* program = argc > 0 ? argv[0] : "machine";
  if (std::optional<std::string> error = parseFlags(argc, argv, options)) {
    std::cerr << "error: " << *error << "\nusage: " << program << kUsage;
    return 2;
  }
  if (options.help) {
    std::cout << "usage: " << program << kUsage << kHelp;
    return 0;
  }
  if (!attachSinks(root, options)) {
    std::cerr << "error: cannot write trace file `" << options.trace_file << "`\n";
    return 2;
  }
  if (options.seed) setRandomSeed(options.seed);
  RunResult result;
  {
    SignalPreempter preempter(root);
    result = run(root);
  }
  if (!result.ok()) {
    std::cerr << "error: " << result.error << "\n";
    return 1;
  }
  if (!options.quiet) std::cout << "outcome: " << result.outcome << "\n";
  if (options.print_userdata) std::cout << "userdata: " << finalUserdata(root) << "\n";
  return 0;
}

}  // namespace smachac::runtime
