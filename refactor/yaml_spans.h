// Where the nodes of a parsed script are written: the byte span of a node from its loader
// location, by reading the YAML text around it. Rules:
//   * a flow collection ends at its matching bracket (quotes and comments skipped)
//   * a quoted scalar ends at its closing quote
//   * a plain scalar in a flow collection ends before the next `,` `]` `}` or comment; in
//     block context at the end of its line (comment and trailing blanks excluded), or of
//     its last continuation line
//   * a block collection or block scalar ends with the last content line indented more
//     than its owner (the mapping key or sequence dash it belongs to); a block sequence that
//     is a key's value may also have dash lines at the key's column; comment lines indented
//     more than the owner count as inside, blank lines never extend a node
//   * an empty value (`key:`) is an empty span right after the colon
// Tags and anchors before a node are skipped.
#pragma once

#include "ir/value.h"
#include "refactor/source_text.h"

namespace smachac::refactor {

/// How a node's surroundings are written: inside a flow collection, or in block context
/// below an owner whose column its continuation lines exceed.
struct Context {
  bool flow = false;
  size_t owner = 0;        ///< 0-based column of the owning key or dash (block context)
  bool under_key = false;  ///< a key's value: a block sequence may sit at the key's column
};

/// The offset where the node's text starts (after any tag or anchor).
size_t nodeStart(const SourceText& text, const ir::Value& node);

/// Whether the node is written in flow style (`{...}` or `[...]`).
bool isFlowCollection(const SourceText& text, const ir::Value& node);

/// The node's text. Not for empty values: use entryValueSpan.
Span nodeSpan(const SourceText& text, const ir::Value& node, Context context);

/// The context of a mapping's values / a sequence's items, given the collection's own.
Context entryContext(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry);
Context itemContext(const SourceText& text, const ir::Value& list);

/// The span of an entry's key, and of its value (empty right after the colon when the
/// value is left out).
Span keySpan(const SourceText& text, const ir::MapEntry& entry);
Span entryValueSpan(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry);

/// `key: value`, from the key to the end of the value.
Span entrySpan(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry);

/// The whole lines of an entry of a block mapping, with the comment lines right above it,
/// through the line break after its value.
Span entryLines(const SourceText& text, const ir::Value& map, const ir::MapEntry& entry);

/// The span of an item of a list (a one-pair mapping in a flow list ends with its value).
Span listItemSpan(const SourceText& text, const ir::Value& list, const ir::Value& item);

/// The last line of a span.
size_t lastLineOf(const SourceText& text, Span span);

}  // namespace smachac::refactor
