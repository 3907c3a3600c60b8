// UTF-8 and Python-compatible character properties and case conversions (see unicode.h).
#include "ir/support/unicode.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace smachac::unicode {
namespace {

bool inRanges(std::span<const CodeRange> table, char32_t cp) {
  auto it = std::upper_bound(table.begin(), table.end(), cp,
                             [](char32_t c, const CodeRange& r) { return c < r.first; });
  return it != table.begin() && cp <= std::prev(it)->last;
}

// Appends the full case mapping of `cp` from `table` (or `cp` itself).
void appendMapped(std::string& out, const CaseTable& table, char32_t cp) {
  auto it = std::lower_bound(table.entries.begin(), table.entries.end(), cp,
                             [](const CaseEntry& e, char32_t c) { return e.cp < c; });
  if (it == table.entries.end() || it->cp != cp) {
    encode(out, cp);
    return;
  }
  for (int i = 0; i < it->length; ++i) encode(out, table.pool[it->offset + i]);
}

std::u32string decodeAll(std::string_view s) {
  std::u32string cps;
  cps.reserve(s.size());
  for (size_t pos = 0; pos < s.size();) cps.push_back(decode(s, pos));
  return cps;
}

constexpr char32_t kCapitalSigma = 0x3A3;

// Python's final-sigma rule: a capital sigma preceded by a cased letter and not followed by
// one (case-ignorable characters are skipped in both directions) lowercases to U+03C2.
bool isFinalSigma(const std::u32string& cps, size_t i) {
  size_t j = i;
  while (j > 0 && isCaseIgnorable(cps[j - 1])) --j;
  if (j == 0 || !isCased(cps[j - 1])) return false;
  size_t k = i + 1;
  while (k < cps.size() && isCaseIgnorable(cps[k])) ++k;
  return k == cps.size() || !isCased(cps[k]);
}

void appendLower(std::string& out, const std::u32string& cps, size_t i) {
  if (cps[i] == kCapitalSigma) {
    encode(out, isFinalSigma(cps, i) ? 0x3C2 : 0x3C3);
    return;
  }
  if (cps[i] < 0x80) {
    char c = static_cast<char>(cps[i]);
    out.push_back(c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c);
    return;
  }
  appendMapped(out, tableToLower(), cps[i]);
}

void appendUpper(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    char c = static_cast<char>(cp);
    out.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c);
    return;
  }
  appendMapped(out, tableToUpper(), cp);
}

}  // namespace

char32_t decode(std::string_view s, size_t& pos) {
  auto byte = [&](size_t i) { return static_cast<unsigned char>(s[i]); };
  unsigned char b0 = byte(pos);
  if (b0 < 0x80) {
    ++pos;
    return b0;
  }
  size_t n = b0 >= 0xF5 ? 0 : b0 >= 0xF0 ? 3 : b0 >= 0xE0 ? 2 : b0 >= 0xC2 ? 1 : 0;
  if (n == 0 || pos + n >= s.size()) {
    ++pos;
    return 0xDC00 + b0;
  }
  char32_t cp = b0 & (0x3F >> n);
  for (size_t i = 1; i <= n; ++i) {
    unsigned char b = byte(pos + i);
    if ((b & 0xC0) != 0x80) {
      ++pos;
      return 0xDC00 + b0;
    }
    cp = (cp << 6) | (b & 0x3F);
  }
  static constexpr char32_t kMin[] = {0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
    ++pos;
    return 0xDC00 + b0;
  }
  pos += n + 1;
  return cp;
}

void encode(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp >= 0xDC80 && cp <= 0xDCFF) {
    out.push_back(static_cast<char>(cp - 0xDC00));  // an undecodable byte, restored
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else if (cp < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

size_t length(std::string_view s) {
  size_t n = 0;
  for (size_t pos = 0; pos < s.size(); ++n) decode(s, pos);
  return n;
}

bool isSpace(char32_t cp) {
  if (cp < 0x80) return (cp >= 0x09 && cp <= 0x0D) || (cp >= 0x1C && cp <= 0x20);
  return cp == 0x85 || cp == 0xA0 || cp == 0x1680 || (cp >= 0x2000 && cp <= 0x200A) ||
         cp == 0x2028 || cp == 0x2029 || cp == 0x202F || cp == 0x205F || cp == 0x3000;
}

bool isPrintable(char32_t cp) {
  if (cp < 0x80) return cp >= 0x20 && cp < 0x7F;
  if (cp >= 0xD800 && cp <= 0xDFFF) return false;  // surrogates (and undecodable bytes)
  return !inRanges(tableNonPrintable(), cp);
}

bool isAlnum(char32_t cp) {
  if (cp < 0x80) {
    return (cp >= '0' && cp <= '9') || (cp >= 'a' && cp <= 'z') || (cp >= 'A' && cp <= 'Z');
  }
  return inRanges(tableAlnum(), cp);
}

bool isLower(char32_t cp) { return inRanges(tableLower(), cp); }
bool isUpper(char32_t cp) { return inRanges(tableUpper(), cp); }
bool isTitle(char32_t cp) { return inRanges(tableTitle(), cp); }
bool isCased(char32_t cp) { return isLower(cp) || isUpper(cp) || isTitle(cp); }
bool isCaseIgnorable(char32_t cp) { return inRanges(tableCaseIgnorable(), cp); }

bool isLineBreak(char32_t cp) {
  return cp == '\n' || cp == '\r' || cp == 0x0B || cp == 0x0C || cp == 0x1C || cp == 0x1D ||
         cp == 0x1E || cp == 0x85 || cp == 0x2028 || cp == 0x2029;
}

std::string toLower(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  bool ascii = std::all_of(s.begin(), s.end(), [](char c) { return (c & 0x80) == 0; });
  if (ascii) {
    for (char c : s) out.push_back(c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c);
    return out;
  }
  std::u32string cps = decodeAll(s);
  for (size_t i = 0; i < cps.size(); ++i) appendLower(out, cps, i);
  return out;
}

std::string toUpper(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t pos = 0; pos < s.size();) appendUpper(out, decode(s, pos));
  return out;
}

std::string capitalize(std::string_view s) {
  std::string out;
  std::u32string cps = decodeAll(s);
  for (size_t i = 0; i < cps.size(); ++i) {
    if (i == 0) {
      appendMapped(out, tableToTitle(), cps[0]);
    } else {
      appendLower(out, cps, i);
    }
  }
  return out;
}

std::string title(std::string_view s) {
  std::string out;
  std::u32string cps = decodeAll(s);
  bool previous_cased = false;
  for (size_t i = 0; i < cps.size(); ++i) {
    if (previous_cased) {
      appendLower(out, cps, i);
    } else {
      appendMapped(out, tableToTitle(), cps[i]);
    }
    previous_cased = isCased(cps[i]);
  }
  return out;
}

std::string swapcase(std::string_view s) {
  std::string out;
  std::u32string cps = decodeAll(s);
  for (size_t i = 0; i < cps.size(); ++i) {
    if (isUpper(cps[i])) {
      appendLower(out, cps, i);
    } else if (isLower(cps[i])) {
      appendUpper(out, cps[i]);
    } else {
      encode(out, cps[i]);
    }
  }
  return out;
}

namespace {

// Whether the 8 bytes at `p` are all spaces or line feeds, which most of the whitespace that
// templates leave around a rendered block is: strip skips such runs 8 bytes at a time.
bool blankWord(const char* p) {
  uint64_t word = 0;
  std::memcpy(&word, p, sizeof word);
  constexpr uint64_t kOnes = 0x0101010101010101ull;
  constexpr uint64_t kLow7 = 0x7F7F7F7F7F7F7F7Full;
  auto zero_bytes = [](uint64_t v) { return ~(((v & kLow7) + kLow7) | v | kLow7); };
  return (zero_bytes(word ^ (kOnes * ' ')) | zero_bytes(word ^ (kOnes * '\n'))) == ~kLow7;
}

}  // namespace

std::string_view strip(std::string_view s, bool left, bool right) {
  auto ascii_space = [](unsigned char c) {
    return (c >= 0x09 && c <= 0x0D) || (c >= 0x1C && c <= 0x20);
  };
  size_t begin = 0;
  size_t end = s.size();
  while (left && end - begin >= 8 && blankWord(s.data() + begin)) begin += 8;
  while (right && end - begin >= 8 && blankWord(s.data() + end - 8)) end -= 8;
  while (left && begin < end) {
    auto c = static_cast<unsigned char>(s[begin]);
    if (c < 0x80) {
      if (!ascii_space(c)) break;
      ++begin;
      continue;
    }
    size_t pos = begin;
    if (!isSpace(decode(s, pos))) break;
    begin = pos;
  }
  while (right && end > begin) {
    auto c = static_cast<unsigned char>(s[end - 1]);
    if (c < 0x80) {
      if (!ascii_space(c)) break;
      --end;
      continue;
    }
    size_t start = end - 1;
    while (start > begin && (static_cast<unsigned char>(s[start]) & 0xC0) == 0x80) --start;
    size_t pos = start;
    char32_t cp = decode(s, pos);
    if (pos != end || !isSpace(cp)) break;
    end = start;
  }
  return s.substr(begin, end - begin);
}

}  // namespace smachac::unicode
