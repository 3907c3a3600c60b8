// Messages from the reader thread to the server loop. The reader parses each frame and
// records `$/cancelRequest` at once, so that a request still waiting in the queue is answered
// "cancelled" instead of being worked on.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "lsp/json_rpc.h"

namespace smachac::lsp {

struct Incoming {
  enum class Kind { Message, ParseError, End } kind = Kind::End;
  Json message;
};

class MessageQueue {
 public:
  void push(Incoming incoming);
  /// Waits for the next message.
  Incoming pop();
  bool empty() const;

  void cancel(const Json& id);
  /// Whether request `id` was cancelled (and forgets it).
  bool takeCancelled(const Json& id);

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Incoming> items_;
  std::set<std::string> cancelled_;  ///< request ids, as JSON text
};

}  // namespace smachac::lsp
