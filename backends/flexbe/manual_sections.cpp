// Manual sections: find each section of the generated text in the existing file, splice.
#include "backends/flexbe/manual_sections.h"

#include <array>

namespace smachac::backends::flexbe {
namespace {

constexpr std::array<std::string_view, 4> kSections = {"IMPORT", "INIT", "CREATE", "FUNC"};

struct Span {
  size_t begin;  ///< first byte after the opening tag's line
  size_t end;    ///< first byte of the closing tag's line
};

enum class Found : uint8_t { Absent, Ok, Broken };

Found findSection(std::string_view text, std::string_view section, Span& span) {
  const std::string open = "# [MANUAL_" + std::string(section) + "]";
  const std::string close = "# [/MANUAL_" + std::string(section) + "]";
  size_t open_at = text.find(open);
  if (open_at == std::string_view::npos) {
    return text.find(close) == std::string_view::npos ? Found::Absent : Found::Broken;
  }
  size_t line_end = text.find('\n', open_at);
  size_t close_at = text.find(close, open_at);
  if (line_end == std::string_view::npos || close_at == std::string_view::npos ||
      close_at < line_end) {
    return Found::Broken;
  }
  size_t close_line = text.rfind('\n', close_at);
  span = {line_end + 1, close_line < line_end ? line_end + 1 : close_line + 1};
  return Found::Ok;
}

}  // namespace

std::optional<std::string> keepManualSections(std::string_view generated,
                                              std::string_view existing) {
  std::string result(generated);
  for (std::string_view section : kSections) {
    Span old_span{};
    Found found = findSection(existing, section, old_span);
    if (found == Found::Broken) return std::nullopt;
    Span new_span{};
    if (found == Found::Absent || findSection(result, section, new_span) != Found::Ok) continue;
    result.replace(new_span.begin, new_span.end - new_span.begin,
                   existing.substr(old_span.begin, old_span.end - old_span.begin));
  }
  return result;
}

}  // namespace smachac::backends::flexbe
