// Edits of a script's text as splices on the original: each replaces a byte range (an
// insertion is an empty range). Rules:
//   * an edit inside a range that another edit replaces is dropped (deleting a key drops the
//     edits of its value); edits that overlap partly are a bug
//   * at one offset, insertions apply in the order they were added, before a replacement
//     that starts there
//   * rendering a range applies the edits inside it (an insertion at its end belongs to the
//     next range, unless the range ends the file) and ignores those that enclose it; an edit
//     that straddles the range's bounds is a bug
// Text outside every edit is copied byte for byte, comments and formatting included.
#pragma once

#include <string>
#include <vector>

#include "refactor/source_text.h"

namespace smachac::refactor {

class EditList {
 public:
  void replace(Span span, std::string text);
  void insert(size_t at, std::string text) { replace({at, at}, std::move(text)); }
  void erase(Span span) { replace(span, {}); }

  /// The source text of `range` with the edits inside it applied.
  std::string render(std::string_view source, Span range) const;

 private:
  struct Edit {
    Span span;
    std::string text;
    size_t order = 0;
  };
  std::vector<Edit> sorted() const;
  /// Whether `edit` applies when rendering `range` (edits enclosing it do not).
  static bool inside(const Edit& edit, Span range, size_t source_size);

  std::vector<Edit> edits_;
};

/// Adds `columns` spaces before every non-empty line of `block`.
std::string indentLines(std::string_view block, size_t columns);

/// Removes up to `columns` leading spaces from every line of `block`.
std::string dedentLines(std::string_view block, size_t columns);

/// `out` with the line breaks of `source`: when the source's first line ends with "\r\n",
/// every bare '\n' (of new text) becomes "\r\n".
std::string withLineBreaksOf(const SourceText& source, std::string out);

}  // namespace smachac::refactor
