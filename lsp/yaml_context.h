// Where a cursor is in a YAML document, from its text alone (the document is often half-typed
// and does not parse): the path of keys and list items from the root to the cursor, whether
// the cursor is where a key, a value or a list item goes, and the word being typed there.
// Block and flow style both; the text is read up to the cursor (yaml_sketch.h), so what
// follows the cursor never changes the context.
//   * Key: a key of the mapping at `path` (`path` does not name the key being typed);
//   * Value: the value of the key that ends `path`;
//   * Item: the item of the list at `path` whose index ends `path`;
//   * None: nowhere a key or a value is typed (after a whole scalar, in a block scalar...).
// A cursor on a blank line is placed by its column: at the column of a mapping's keys it is at
// a key of that mapping; deeper than a key without a value, at a key of a new mapping under it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::lsp {

/// A mapping key, or (index >= 0) a list item.
struct PathSegment {
  std::string key;
  int64_t index = -1;

  bool isItem() const { return index >= 0; }
  friend bool operator==(const PathSegment&, const PathSegment&) = default;
};

enum class CursorRole : uint8_t { None, Key, Value, Item };

struct YamlContext {
  std::vector<PathSegment> path;
  CursorRole role = CursorRole::None;
  bool in_flow = false;     ///< the innermost collection is written in flow style
  bool in_comment = false;  ///< after a `#` that starts a comment
  bool quoted = false;      ///< in a quoted scalar (its quotes are not part of the word)
  bool in_code = false;     ///< in a scalar that starts with a backtick (target code)
  std::string prefix;       ///< the part of the word before the cursor
  size_t word_begin = 0;    ///< byte offsets of the word around the cursor in the text
  size_t word_end = 0;
};

/// The context of the cursor at byte `offset` of `text`.
YamlContext yamlContextAt(std::string_view text, size_t offset);

/// The path as `states/[2]/PICK/transitions` (for tests and logs).
std::string describePath(const std::vector<PathSegment>& path);

/// Whether `c` can be part of a word typed as a key or a name (letters, digits, `_-./`, and
/// every byte of a UTF-8 sequence).
bool isWordByte(char c);

}  // namespace smachac::lsp
