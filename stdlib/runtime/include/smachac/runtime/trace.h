// Trace: what a running machine reports, one event at a time, to a TraceSink attached with
// State::setTraceSink (usually on the root).
//
//   enter       a container starts a child               {state}
//   exit        the child returned                       {state, outcome, written}
//   transition  a StateMachine resolved that outcome     {state, outcome, target, terminal}
//   preempt     a state received a preempt request       {state}
//   error       a child failed (exception, bad outcome)  {state, message}
//
// `state` is the path ("SUB/FOO"; "" is the root), `written` the keys the state wrote in its
// parent's userdata (after remapping), `t_us` microseconds of steady_clock since the sink was
// made. Sinks are called from several threads (Concurrence) and serialise themselves.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::runtime {

enum class TraceKind : uint8_t { Enter, Exit, Transition, Preempt, Error };

/// "enter", "exit", "transition", "preempt", "error".
std::string_view traceKindName(TraceKind kind);

/// One event; the views live only during TraceSink::write.
struct TraceEvent {
  TraceKind kind = TraceKind::Enter;
  std::string_view state{};
  std::string_view outcome{};
  std::string_view target{};
  bool terminal = false;
  std::string_view message{};
  const std::vector<std::string>* written = nullptr;
  std::chrono::steady_clock::time_point time = std::chrono::steady_clock::now();
};

class TraceSink {
 public:
  TraceSink() : start_(std::chrono::steady_clock::now()) {}
  virtual ~TraceSink() = default;
  TraceSink(const TraceSink&) = delete;
  TraceSink& operator=(const TraceSink&) = delete;

  /// Called from any thread.
  virtual void write(const TraceEvent& event) = 0;

 protected:
  int64_t micros(const TraceEvent& event) const;

 private:
  std::chrono::steady_clock::time_point start_;
};

/// {"t_us":12,"event":"exit","state":"SUB/FOO","outcome":"succeeded","written":["x"]}
std::string formatJsonLine(const TraceEvent& event, int64_t t_us);
/// [    0.000012] exit SUB/FOO -> succeeded (wrote x)
std::string formatLogLine(const TraceEvent& event, int64_t t_us);

/// JSON lines, one per event, flushed per line.
class JsonLinesSink : public TraceSink {
 public:
  explicit JsonLinesSink(std::ostream& out) : out_(out) {}
  void write(const TraceEvent& event) override;

 private:
  std::mutex mutex_;
  std::ostream& out_;
};

/// Human-readable lines.
class LogSink : public TraceSink {
 public:
  explicit LogSink(std::ostream& out) : out_(out) {}
  void write(const TraceEvent& event) override;

 private:
  std::mutex mutex_;
  std::ostream& out_;
};

/// Keeps every event (tests, the simulation's checks).
class RecordingSink : public TraceSink {
 public:
  struct Record {
    TraceKind kind;
    std::string state;
    std::string outcome;
    std::string target;
    bool terminal;
    std::string message;
    std::vector<std::string> written;
    int64_t t_us;
  };
  void write(const TraceEvent& event) override;
  std::vector<Record> records() const;
  /// Compact lines without times: "enter FOO", "exit FOO succeeded", "transition FOO
  /// succeeded BAR", "preempt SUB", "error FOO <message>".
  std::vector<std::string> lines() const;

 private:
  mutable std::mutex mutex_;
  std::vector<Record> records_;
};

/// Forwards every event to several sinks.
class TeeSink : public TraceSink {
 public:
  explicit TeeSink(std::vector<std::shared_ptr<TraceSink>> sinks) : sinks_(std::move(sinks)) {}
  void write(const TraceEvent& event) override;

 private:
  std::vector<std::shared_ptr<TraceSink>> sinks_;
};

}  // namespace smachac::runtime
