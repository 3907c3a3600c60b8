// TemplateError formatting and the "did you mean" suggestion helper.
#include "backends/tmpl/error.h"

#include <algorithm>

#include "ir/support/suggest.h"

namespace smachac::tmpl {

TemplateError::TemplateError(std::string file, int line, int column, std::string message)
    : file_(std::move(file)), line_(line), column_(column), message_(std::move(message)) {
  what_ = file_;
  if (line_ > 0) what_ += ":" + std::to_string(line_) + ":" + std::to_string(column_);
  what_ += ": " + message_;
}

void fail(std::string message) { throw Fault(std::move(message)); }

std::string didYouMean(std::string_view name, const std::vector<std::string_view>& candidates) {
  // Sorted, so that of equally close names the first in alphabetical order is suggested.
  std::vector<std::string> sorted(candidates.begin(), candidates.end());
  std::sort(sorted.begin(), sorted.end());
  return smachac::didYouMean(name, sorted);
}

}  // namespace smachac::tmpl
