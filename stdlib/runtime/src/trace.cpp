// Trace events as JSON lines and readable lines, and the sinks that write or keep them.
#include "smachac/runtime/trace.h"

#include <cstdio>
#include <ostream>

#include "text.h"

namespace smachac::runtime {

namespace {

void appendJsonString(std::string& out, std::string_view text) {
  appendQuoted(out, text, '"', Escape::Json);
}

void appendField(std::string& out, std::string_view name, std::string_view value) {
  out += ",\"";
  out += name;
  out += "\":";
  appendJsonString(out, value);
}

bool hasOutcome(TraceKind kind) { return kind == TraceKind::Exit || kind == TraceKind::Transition; }

std::string shownPath(std::string_view path) { return path.empty() ? "<root>" : std::string(path); }

std::string joined(const std::vector<std::string>& keys) {
  std::string out;
  for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
  return out;
}

}  // namespace

std::string_view traceKindName(TraceKind kind) {
  switch (kind) {
    case TraceKind::Enter:
      return "enter";
    case TraceKind::Exit:
      return "exit";
    case TraceKind::Transition:
      return "transition";
    case TraceKind::Preempt:
      return "preempt";
    case TraceKind::Error:
      return "error";
  }
  return "?";
}

int64_t TraceSink::micros(const TraceEvent& event) const {
  return std::chrono::duration_cast<std::chrono::microseconds>(event.time - start_).count();
}

std::string formatJsonLine(const TraceEvent& event, int64_t t_us) {
  std::string out = "{\"t_us\":" + std::to_string(t_us);
  appendField(out, "event", traceKindName(event.kind));
  appendField(out, "state", event.state);
  if (hasOutcome(event.kind)) appendField(out, "outcome", event.outcome);
  if (event.kind == TraceKind::Transition) {
    appendField(out, "target", event.target);
    out += event.terminal ? ",\"terminal\":true" : ",\"terminal\":false";
  }
  if (event.kind == TraceKind::Error) appendField(out, "message", event.message);
  if (event.kind == TraceKind::Exit && event.written != nullptr) {
    out += ",\"written\":[";
    for (std::size_t i = 0; i < event.written->size(); ++i) {
      if (i > 0) out += ',';
      appendJsonString(out, (*event.written)[i]);
    }
    out += ']';
  }
  return out + "}";
}

std::string formatLogLine(const TraceEvent& event, int64_t t_us) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "[%12.6f] ", static_cast<double>(t_us) / 1e6);
  std::string out = stamp;
  std::string state = shownPath(event.state);
  switch (event.kind) {
    case TraceKind::Enter:
      return out + "enter " + state;
    case TraceKind::Exit:
      out += "exit " + state + " -> " + std::string(event.outcome);
      if (event.written != nullptr && !event.written->empty()) {
        out += " (wrote " + joined(*event.written) + ")";
      }
      return out;
    case TraceKind::Transition:
      return out + "transition " + state + " --" + std::string(event.outcome) + "--> " +
             std::string(event.target) + (event.terminal ? " (container outcome)" : "");
    case TraceKind::Preempt:
      return out + "preempt " + state;
    case TraceKind::Error:
      return out + "error " + state + ": " + std::string(event.message);
  }
  return out;
}

void JsonLinesSink::write(const TraceEvent& event) {
  std::string line = formatJsonLine(event, micros(event)) + "\n";
  std::lock_guard lock(mutex_);
  out_ << line << std::flush;
}

void LogSink::write(const TraceEvent& event) {
  std::string line = formatLogLine(event, micros(event)) + "\n";
  std::lock_guard lock(mutex_);
  out_ << line << std::flush;
}

void RecordingSink::write(const TraceEvent& event) {
  Record record{.kind = event.kind,
                .state = std::string(event.state),
                .outcome = std::string(event.outcome),
                .target = std::string(event.target),
                .terminal = event.terminal,
                .message = std::string(event.message),
                .written = event.written != nullptr ? *event.written : std::vector<std::string>{},
                .t_us = micros(event)};
  std::lock_guard lock(mutex_);
  records_.push_back(std::move(record));
}

std::vector<RecordingSink::Record> RecordingSink::records() const {
  std::lock_guard lock(mutex_);
  return records_;
}

std::vector<std::string> RecordingSink::lines() const {
  std::vector<std::string> out;
  for (const Record& r : records()) {
    std::string line = std::string(traceKindName(r.kind)) + " " + r.state;
    if (hasOutcome(r.kind)) line += " " + r.outcome;
    if (r.kind == TraceKind::Transition) line += " " + r.target;
    if (r.kind == TraceKind::Error) line += " " + r.message;
    out.push_back(std::move(line));
  }
  return out;
}

void TeeSink::write(const TraceEvent& event) {
  for (const auto& sink : sinks_) sink->write(event);
}

}  // namespace smachac::runtime
