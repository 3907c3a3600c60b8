// Manual sections: find each section of the generated text in the existing file, splice. A tag
// counts only alone on its line: a string value holding `# [MANUAL_CREATE]` is no tag.
#include "backends/flexbe/manual_sections.h"

#include <algorithm>
#include <array>

namespace smachac::backends::flexbe {
namespace {

constexpr std::array<std::string_view, 4> kSections = {"IMPORT", "INIT", "CREATE", "FUNC"};

struct Span {
  size_t begin;  ///< first byte after the opening tag's line
  size_t end;    ///< first byte of the closing tag's line
};

enum class Found : uint8_t { Absent, Ok, Broken };

bool onlySpaces(std::string_view text) {
  return text.find_first_not_of(" \t\r") == std::string_view::npos;
}

/// The position of the first `tag` at or after `from` that is alone on its line (indentation
/// and trailing blanks aside), so that the same text inside a string literal is no tag.
size_t findTagLine(std::string_view text, std::string_view tag, size_t from = 0) {
  for (size_t at = text.find(tag, from); at != std::string_view::npos;
       at = text.find(tag, at + 1)) {
    size_t line_start = text.rfind('\n', at);
    line_start = line_start == std::string_view::npos ? 0 : line_start + 1;
    size_t line_end = std::min(text.find('\n', at), text.size());
    size_t tag_end = at + tag.size();
    if (onlySpaces(text.substr(line_start, at - line_start)) &&
        onlySpaces(text.substr(tag_end, line_end - tag_end))) {
      return at;
    }
  }
  return std::string_view::npos;
}

Found findSection(std::string_view text, std::string_view section, Span& span) {
  const std::string open = "# [MANUAL_" + std::string(section) + "]";
  const std::string close = "# [/MANUAL_" + std::string(section) + "]";
  size_t open_at = findTagLine(text, open);
  if (open_at == std::string_view::npos) {
    return findTagLine(text, close) == std::string_view::npos ? Found::Absent : Found::Broken;
  }
  size_t line_end = text.find('\n', open_at);
  size_t close_at = findTagLine(text, close, open_at);
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
