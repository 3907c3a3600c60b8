// The lexical half of the simple YAML reader (simple_yaml_reader.h): a cursor over the text
// that keeps yaml-cpp's 0-based line and byte column, and scanners for one-line scalars.
// Every scanner returns false when the text is not certainly what it handles; the reader then
// gives up and yaml-cpp parses the text.
#pragma once

#include <string>
#include <string_view>

#include "frontend/yaml_value_builder.h"

namespace smachac::frontend {

struct YamlCursor {
  std::string_view text;
  size_t pos = 0;
  int line = 0;
  size_t line_start = 0;

  /// The byte `ahead` bytes on, '\0' past the end (the text holds no NUL byte).
  char peek(size_t ahead = 0) const { return pos + ahead < text.size() ? text[pos + ahead] : '\0'; }
  bool atEnd() const { return pos >= text.size(); }
  bool atLineEnd() const { return pos >= text.size() || text[pos] == '\n'; }
  int column() const { return static_cast<int>(pos - line_start); }
  YamlMark mark() const { return {line, column()}; }
  void skipSpaces() {
    while (pos < text.size() && text[pos] == ' ') ++pos;
  }
  /// Moves past the rest of the line and its line break (stays on a last line without one).
  void nextLine();
};

/// A scanned scalar: its text (a view of the document, or `owned` after unescaping).
struct YamlScalar {
  YamlMark mark;
  bool quoted = false;
  std::string_view text;
  std::string owned;
};

enum class YamlContext { Block, Flow };

/// True for text that the simple reader may handle at all: no tab, carriage return or other
/// control byte, no byte order mark and no Unicode line break anywhere.
bool hasOnlySimpleBytes(std::string_view text);

/// True when a plain scalar the reader handles starts at the cursor.
bool startsSimplePlain(const YamlCursor& cursor);

/// A plain scalar on one line. Stops before `: `/`:` at the line end, before ` #`, at the line
/// end, and in flow context also before `,[]{}`; trailing spaces are not part of it.
bool scanPlain(YamlCursor& cursor, YamlContext context, YamlScalar& out);

/// A single- or double-quoted scalar on one line; the cursor is on the opening quote.
bool scanQuoted(YamlCursor& cursor, YamlScalar& out);

/// yaml-cpp reports these plain scalars as null nodes.
bool isNullPlain(std::string_view text);

}  // namespace smachac::frontend
