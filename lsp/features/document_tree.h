// The YAML tree that outline features (symbols, folding, completion) read: the document's
// parsed tree, or, when its text does not parse, the tolerant sketch of the text
// (lsp/yaml_sketch.h), so that a half-typed document keeps its outline. Both locate every
// node in the document; `nodeEnd` says where a node's text ends.
#pragma once

#include <optional>
#include <string_view>

#include "ir/value.h"
#include "lsp/analysis.h"

namespace smachac::lsp {

class DocumentTree {
 public:
  explicit DocumentTree(const Analysis& analysis);
  DocumentTree(const DocumentTree&) = delete;
  DocumentTree& operator=(const DocumentTree&) = delete;

  const ir::Value& root() const { return sketch_ ? *sketch_ : *analysis_.yaml; }
  /// True when the text did not parse and the tree is the sketch.
  bool sketched() const { return sketch_.has_value(); }

 private:
  const Analysis& analysis_;
  std::optional<ir::Value> sketch_;
};

/// The byte offset just after `node` in `text` (the document its locations refer to): after
/// its last key or scalar, or after the bracket that closes a flow collection.
size_t nodeEnd(const ir::Value& node, const LineIndex& lines, std::string_view text);

/// The mapping entry of `map` whose key is `key` or SMACHA's shorthand of it, or null.
const ir::MapEntry* findKey(const ir::Value& map, std::string_view key);

}  // namespace smachac::lsp
