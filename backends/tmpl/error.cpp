// TemplateError formatting and the "did you mean" suggestion helper.
#include "backends/tmpl/error.h"

#include <algorithm>

namespace smachac::tmpl {

TemplateError::TemplateError(std::string file, int line, int column, std::string message)
    : file_(std::move(file)), line_(line), column_(column), message_(std::move(message)) {
  what_ = file_;
  if (line_ > 0) what_ += ":" + std::to_string(line_) + ":" + std::to_string(column_);
  what_ += ": " + message_;
}

void fail(std::string message) { throw Fault(std::move(message)); }

namespace {

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string didYouMean(std::string_view name, const std::vector<std::string_view>& candidates) {
  size_t limit = std::max<size_t>(1, name.size() / 3);
  std::string_view best;
  size_t bestDistance = limit + 1;
  for (std::string_view candidate : candidates) {
    size_t d = editDistance(name, candidate);
    if (d < bestDistance || (d == bestDistance && candidate < best)) {
      best = candidate;
      bestDistance = d;
    }
  }
  if (best.empty()) return "";
  return "; did you mean `" + std::string(best) + "`?";
}

}  // namespace smachac::tmpl
