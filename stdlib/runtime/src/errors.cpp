// The runtime's exceptions: ConsistencyError joins its problems into one message.
#include "smachac/runtime/errors.h"

namespace smachac::runtime {

namespace {

std::string joinLines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) {
    if (!text.empty()) text += '\n';
    text += line;
  }
  return text;
}

}  // namespace

ConsistencyError::ConsistencyError(std::vector<std::string> problems)
    : Error(joinLines(problems)), problems_(std::move(problems)) {}

}  // namespace smachac::runtime
