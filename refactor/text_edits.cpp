// Splicing edits into the original text.
#include "refactor/text_edits.h"

#include <algorithm>

#include "ir/support/check.h"

namespace smachac::refactor {

void EditList::replace(Span span, std::string text) {
  SMACHAC_CHECK(span.begin <= span.end, "an edit must not end before it starts");
  edits_.push_back({span, std::move(text), edits_.size()});
}

std::vector<EditList::Edit> EditList::sorted() const {
  std::vector<Edit> edits = edits_;
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
    if (a.span.begin != b.span.begin) return a.span.begin < b.span.begin;
    bool a_insert = a.span.begin == a.span.end;
    bool b_insert = b.span.begin == b.span.end;
    if (a_insert != b_insert) return a_insert;
    if (a.span.end != b.span.end) return a.span.end > b.span.end;
    return a.order < b.order;
  });
  return edits;
}

bool EditList::inside(const Edit& edit, Span range, size_t source_size) {
  if (edit.span.begin == edit.span.end) {
    size_t p = edit.span.begin;
    return (p >= range.begin && p < range.end) || (p == range.end && p == source_size);
  }
  if (edit.span.begin >= range.begin && edit.span.end <= range.end) return true;
  bool outside = edit.span.end <= range.begin || edit.span.begin >= range.end;
  bool enclosing = edit.span.begin <= range.begin && edit.span.end >= range.end;
  SMACHAC_CHECK(outside || enclosing, "an edit straddles the bounds of a rendered range");
  return false;
}

std::string EditList::render(std::string_view source, Span range) const {
  std::string out;
  size_t at = range.begin;
  for (const Edit& edit : sorted()) {
    if (!inside(edit, range, source.size())) continue;
    if (edit.span.begin < at) {
      SMACHAC_CHECK(edit.span.end <= at, "overlapping edits");
      continue;  // inside a range an earlier edit replaced
    }
    out.append(source.substr(at, edit.span.begin - at));
    out += edit.text;
    at = edit.span.end;
  }
  out.append(source.substr(at, range.end - at));
  return out;
}

std::string indentLines(std::string_view block, size_t columns) {
  std::string out;
  bool line_start = true;
  for (char c : block) {
    if (line_start && c != '\n' && c != '\r') out.append(columns, ' ');
    out += c;
    line_start = c == '\n';
  }
  return out;
}

std::string dedentLines(std::string_view block, size_t columns) {
  std::string out;
  size_t skip = columns;
  for (char c : block) {
    if (c == ' ' && skip > 0) {
      --skip;
      continue;
    }
    skip = c == '\n' ? columns : 0;
    out += c;
  }
  return out;
}

std::string withLineBreaksOf(const SourceText& source, std::string out) {
  size_t first = source.lineEnd(0);
  if (first == 0 || first >= source.size() || source.at(first - 1) != '\r') return out;
  std::string converted;
  converted.reserve(out.size() + out.size() / 16);
  for (size_t i = 0; i < out.size(); ++i) {
    if (out[i] == '\n' && (i == 0 || out[i - 1] != '\r')) converted += '\r';
    converted += out[i];
  }
  return converted;
}

}  // namespace smachac::refactor
