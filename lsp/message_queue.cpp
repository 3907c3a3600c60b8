// The queue between the reader thread and the server loop.
#include "lsp/message_queue.h"

namespace smachac::lsp {

void MessageQueue::push(Incoming incoming) {
  {
    std::lock_guard lock(mutex_);
    items_.push_back(std::move(incoming));
  }
  ready_.notify_one();
}

Incoming MessageQueue::pop() {
  std::unique_lock lock(mutex_);
  ready_.wait(lock, [this] { return !items_.empty(); });
  Incoming incoming = std::move(items_.front());
  items_.pop_front();
  return incoming;
}

bool MessageQueue::empty() const {
  std::lock_guard lock(mutex_);
  return items_.empty();
}

void MessageQueue::cancel(const Json& id) {
  std::lock_guard lock(mutex_);
  cancelled_.insert(id.dump());
}

bool MessageQueue::takeCancelled(const Json& id) {
  std::lock_guard lock(mutex_);
  return cancelled_.erase(id.dump()) > 0;
}

}  // namespace smachac::lsp
