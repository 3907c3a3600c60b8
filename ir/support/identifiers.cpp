// Identifier rules per target: character classes, keywords and reserved names.
#include "ir/support/identifiers.h"

#include <fmt/core.h>

#include <algorithm>
#include <span>

#include "ir/support/python_keywords.h"
#include "ir/support/python_text.h"

namespace smachac {
namespace {

// C++20 keywords and alternative tokens.
constexpr std::string_view kCppKeywords[] = {"alignas",       "alignof",     "and",
                                             "and_eq",        "asm",         "auto",
                                             "bitand",        "bitor",       "bool",
                                             "break",         "case",        "catch",
                                             "char",          "char8_t",     "char16_t",
                                             "char32_t",      "class",       "compl",
                                             "concept",       "const",       "consteval",
                                             "constexpr",     "constinit",   "const_cast",
                                             "continue",      "co_await",    "co_return",
                                             "co_yield",      "decltype",    "default",
                                             "delete",        "do",          "double",
                                             "dynamic_cast",  "else",        "enum",
                                             "explicit",      "export",      "extern",
                                             "false",         "float",       "for",
                                             "friend",        "goto",        "if",
                                             "inline",        "int",         "long",
                                             "mutable",       "namespace",   "new",
                                             "noexcept",      "not",         "not_eq",
                                             "nullptr",       "operator",    "or",
                                             "or_eq",         "private",     "protected",
                                             "public",        "register",    "reinterpret_cast",
                                             "requires",      "return",      "short",
                                             "signed",        "sizeof",      "static",
                                             "static_assert", "static_cast", "struct",
                                             "switch",        "template",    "this",
                                             "thread_local",  "throw",       "true",
                                             "try",           "typedef",     "typeid",
                                             "typename",      "union",       "unsigned",
                                             "using",         "virtual",     "void",
                                             "volatile",      "wchar_t",     "while",
                                             "xor",           "xor_eq"};

bool isKeyword(std::string_view text, std::span<const std::string_view> keywords) {
  return std::find(keywords.begin(), keywords.end(), text) != keywords.end();
}

std::string describeChar(char c) {
  auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x80) return "a non-ASCII character";
  if (byte < 0x20 || byte == 0x7f) return fmt::format("the control character 0x{:02x}", byte);
  if (c == ' ') return "a space";
  if (c == '`') return "a backtick";
  return fmt::format("`{}`", c);
}

std::optional<std::string> characterProblem(std::string_view text) {
  if (text.empty()) return "is empty";
  if (text[0] >= '0' && text[0] <= '9') return "starts with a digit";
  auto bad = std::find_if_not(text.begin(), text.end(), isIdentifierChar);
  if (bad != text.end()) return "contains " + describeChar(*bad);
  return std::nullopt;
}

}  // namespace

IdentifierRules identifierRules(std::string_view target) {
  if (target == "smach" || target == "smach_ros" || target == "flexbe") {
    return IdentifierRules::Python;
  }
  if (target == "cpp") return IdentifierRules::Cpp;
  return IdentifierRules::None;
}

std::string_view rulesName(IdentifierRules rules) {
  return rules == IdentifierRules::Cpp ? "C++" : "Python";
}

bool isAsciiIdentifier(std::string_view text) { return !characterProblem(text); }

std::optional<std::string> identifierProblem(std::string_view text, IdentifierRules rules) {
  if (rules == IdentifierRules::None) return std::nullopt;
  if (std::optional<std::string> problem = characterProblem(text)) return problem;
  if (rules == IdentifierRules::Python) {
    if (isKeyword(text, kPythonKeywords)) return std::string("is a keyword");
    return std::nullopt;
  }
  if (isKeyword(text, kCppKeywords)) return std::string("is a keyword");
  if (text.find("__") != std::string_view::npos) return std::string("contains `__` (reserved)");
  if (text.size() > 1 && text[0] == '_' && text[1] >= 'A' && text[1] <= 'Z') {
    return std::string("starts with `_` and a capital letter (reserved)");
  }
  return std::nullopt;
}

std::string asciiLower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return lower;
}

}  // namespace smachac
