// UTF-8 decoding/encoding and the Unicode character properties that Python's str methods use
// (isspace, isprintable, isalnum, case mapping with final sigma). The property tables are
// generated from Python 3.11 by ir/support/tools/gen_unicode_tables.py (unicode_tables.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace smachac::unicode {

struct CodeRange {
  char32_t first;
  char32_t last;
};

struct CaseEntry {
  char32_t cp;
  uint16_t offset;
  uint8_t length;
};

struct CaseTable {
  std::span<const CaseEntry> entries;
  const char32_t* pool;
};

// Generated tables (unicode_tables.cpp).
std::span<const CodeRange> tableNonPrintable();
std::span<const CodeRange> tableAlnum();
std::span<const CodeRange> tableLower();
std::span<const CodeRange> tableUpper();
std::span<const CodeRange> tableTitle();
std::span<const CodeRange> tableCaseIgnorable();
CaseTable tableToLower();
CaseTable tableToUpper();
CaseTable tableToTitle();

/// Decodes the code point at `pos` and advances `pos`. Invalid bytes decode as themselves
/// (U+0080..U+00FF is never produced for them; they map to 0xDC80 + byte, like Python's
/// surrogateescape) so that no input can make decoding fail.
char32_t decode(std::string_view s, size_t& pos);
void encode(std::string& out, char32_t cp);
size_t length(std::string_view s);  // number of code points

bool isSpace(char32_t cp);  // Python str.isspace
bool isPrintable(char32_t cp);
bool isAlnum(char32_t cp);
bool isLower(char32_t cp);
bool isUpper(char32_t cp);
bool isTitle(char32_t cp);
bool isCased(char32_t cp);
bool isCaseIgnorable(char32_t cp);
bool isLineBreak(char32_t cp);  // Python str.splitlines boundaries

std::string toLower(std::string_view s);  // Python str.lower (with final sigma)
std::string toUpper(std::string_view s);
std::string capitalize(std::string_view s);  // Python str.capitalize
std::string title(std::string_view s);       // Python str.title
std::string swapcase(std::string_view s);

/// Python str.strip/lstrip/rstrip with no argument (whitespace).
std::string_view strip(std::string_view s, bool left = true, bool right = true);

}  // namespace smachac::unicode
