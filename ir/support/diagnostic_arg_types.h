// The argument types of diagnostics beyond text and numbers (diagnostic_kinds.def and
// diagnostic_notes.def declare which kind takes which), each printed by fmt:
//  * ForeignMessage: a message that another component wrote (yaml-cpp, the template engine)
//    and a diagnostic passes on unchanged. It is built explicitly, so that no text of
//    smachac's own goes through a kind whose message is only that argument by accident.
//  * choices: a closed set of texts, one per enumerator, written here (clang's %select): the
//    caller names the case, the registry owns the words.
//  * Numbered<Choice>: a choice whose text shows a number where it has `{}`.
// Rules: a choice's texts are printed as written (braces included), except the one `{}` of a
// Numbered choice; every switch covers every enumerator (no default).
#pragma once

#include <fmt/core.h>

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>

namespace smachac {

struct ForeignMessage {
  explicit ForeignMessage(std::string_view message) : text(message) {}
  std::string_view text;
};

/// What makes a script's bytes no YAML text (invalid-encoding).
enum class EncodingProblem : uint8_t { NulByte, InvalidUtf8 };

constexpr std::string_view choiceText(EncodingProblem problem) {
  switch (problem) {
    case EncodingProblem::NulByte:
      return "NUL byte in YAML text";
    case EncodingProblem::InvalidUtf8:
      return "invalid UTF-8 byte sequence";
  }
  return "";
}

/// The limit of the YAML reader that a document exceeds (yaml-too-complex); `{}` is the limit.
enum class YamlLimit : uint8_t { Nodes, AliasMebibytes, Depth, ParserDepth };

constexpr std::string_view choiceText(YamlLimit limit) {
  switch (limit) {
    case YamlLimit::Nodes:
      return "document expands to more than {} nodes (aliases included)";
    case YamlLimit::AliasMebibytes:
      return "aliases copy more than {} MiB of text";
    case YamlLimit::Depth:
      return "nested more than {} levels deep";
    case YamlLimit::ParserDepth:
      return "nested too deeply for the parser";  // yaml-cpp's own limit, which it does not say
  }
  return "";
}

/// What a syntax error of yaml-cpp probably means in a script (the note yaml-syntax-hint):
/// yaml-cpp names the parser's state, not the mistake, which is nearly always the indentation
/// of the line or a missing `- `.
enum class YamlSyntaxHint : uint8_t {
  IndentLikeSiblings,
  CloseList,
  CloseMapping,
  KeyTooDeep,
  EntryOnOwnLine
};

constexpr std::string_view choiceText(YamlSyntaxHint hint) {
  switch (hint) {
    case YamlSyntaxHint::IndentLikeSiblings:
      return "this line is indented like no key above it: indent it as its sibling keys are, or "
             "start a new list entry (a state) with `- `";
    case YamlSyntaxHint::CloseList:
      return "a `[` list is not closed: add its `]`, also when the list spans several lines";
    case YamlSyntaxHint::CloseMapping:
      return "a `{` mapping is not closed: add its `}`, also when the mapping spans several lines";
    case YamlSyntaxHint::KeyTooDeep:
      return "a `key:` here is not at the indentation of a mapping: the line is indented deeper "
             "than the key above it, or a `- ` is missing before it";
    case YamlSyntaxHint::EntryOnOwnLine:
      return "a `- ` list entry must begin a line of its own, indented under its key";
  }
  return "";
}

template <typename Choice>
concept DiagChoice = requires(Choice choice) {
  { choiceText(choice) } -> std::same_as<std::string_view>;
};

template <DiagChoice Choice>
struct Numbered {
  Choice choice;
  uint64_t number = 0;
};
/// `Numbered{choice, n}` without naming the choice type (clang before 17 does not deduce an
/// aggregate's template arguments by itself).
template <DiagChoice Choice>
Numbered(Choice, uint64_t) -> Numbered<Choice>;

/// The text of a Numbered choice: its `{}` (if any) replaced by the number.
template <DiagChoice Choice>
std::string numberedText(const Numbered<Choice>& numbered) {
  std::string text(choiceText(numbered.choice));
  size_t field = text.find("{}");
  if (field != std::string::npos) text.replace(field, 2, std::to_string(numbered.number));
  return text;
}

}  // namespace smachac

namespace smachac {

/// fmt's formatting of the types above: their text as it is, with no format spec (fmt's own
/// formatter<string_view> would need <fmt/format.h> in every file that reports a diagnostic).
struct DiagTextFormatter {
  constexpr auto parse(fmt::format_parse_context& context) { return context.begin(); }
  static auto write(std::string_view text, fmt::format_context& context) {
    return std::copy(text.begin(), text.end(), context.out());
  }
};

}  // namespace smachac

template <>
struct fmt::formatter<smachac::ForeignMessage> : smachac::DiagTextFormatter {
  auto format(const smachac::ForeignMessage& message, fmt::format_context& context) const {
    return write(message.text, context);
  }
};

template <smachac::DiagChoice Choice>
struct fmt::formatter<Choice> : smachac::DiagTextFormatter {
  auto format(Choice choice, fmt::format_context& context) const {
    return write(choiceText(choice), context);
  }
};

template <smachac::DiagChoice Choice>
struct fmt::formatter<smachac::Numbered<Choice>> : smachac::DiagTextFormatter {
  auto format(const smachac::Numbered<Choice>& numbered, fmt::format_context& context) const {
    return write(numberedText(numbered), context);
  }
};
