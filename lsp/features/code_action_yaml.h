// Small edits of a document's YAML for the quick fixes, in the style the script is written
// in (refactor/map_edits.h does the mappings). Rules:
//   * a state's mapping is found by its name's location: the lowered state's name is the key
//     of its `NAME: {...}` entry in a `states` list (nested lists flattened); the root state's
//     mapping is the document's root
//   * adding a name to a list key: a flow list gets `, name` after its last item (`name`
//     inside `[]`), a block list a new `- name` line like its last item's; a key left empty
//     gets `[name]`; a missing key is added to the mapping as `key: [name]` (spelled in
//     shorthand when the mapping uses shorthand)
//   * adding an entry to a mapping key: the same, with `{key: value}` for a new or empty key
//   * anything else (a scalar where a list should be, a list item that is not on its own
//     `- ` line) is left alone: the edit reports false
// The result is the whole new text, with the document's line breaks (CRLF kept).
#pragma once

#include <string>
#include <string_view>

#include "ir/state.h"
#include "ir/value.h"
#include "refactor/text_edits.h"

namespace smachac::lsp {

/// The mapping of `state` in the YAML tree `root`, or nullptr.
const ir::Value* stateMapping(const ir::Value& root, const ir::State& state);

class YamlEdit {
 public:
  explicit YamlEdit(std::string_view text) : text_(std::string(text)) {}

  /// Adds `name` to the list under key `longhand` of `mapping`.
  bool addToList(const ir::Value& mapping, std::string_view longhand, std::string_view name);
  /// Adds `key: value` (value already YAML text) to the mapping under key `longhand`.
  bool addToMap(const ir::Value& mapping, std::string_view longhand, std::string_view key,
                std::string_view value);

  /// The text with the edits made.
  std::string result() const;

 private:
  /// `item` is YAML text.
  bool appendListItem(const ir::Value& list, std::string_view item);
  bool appendBlockItem(const ir::Value& list, std::string_view item);

  refactor::SourceText text_;
  refactor::EditList edits_;
};

}  // namespace smachac::lsp
