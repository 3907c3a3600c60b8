// A compiled template: its normalised source (which the tokens and AST point into), the parsed
// statements with their scope layout, its blocks and the templates it references.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/ast.h"
#include "backends/tmpl/builtins.h"
#include "backends/tmpl/error.h"

namespace smachac::tmpl {

/// Which blocks of a template one skip policy removes (a cache the renderer fills).
struct SkipMask {
  const std::string* only;
  const void* scope;
  std::vector<const std::string*> names;
  std::vector<char> skipped;  // by BlockStmt::index
  Value module;               // the template's default module under this policy (imports)
};

class Template {
 public:
  /// Compiles `source`; raises TemplateError (syntax error, unknown filter or test).
  /// `origin` is what errors name (a file path, or `<builtin>/smach/State.tpl.py`).
  Template(std::string name, std::string origin, std::string_view source, const Registry& registry);
  Template(const Template&) = delete;
  Template& operator=(const Template&) = delete;

  const std::string& name() const { return name_; }
  const std::string& origin() const { return origin_; }
  std::string_view source() const { return source_; }
  const Body& body() const { return body_; }
  const FrameLayout& rootFrame() const { return rootFrame_; }
  const std::vector<BlockStmt*>& blocks() const { return blocks_; }
  const BlockStmt* block(std::string_view name) const;
  /// String-literal names of the templates it extends, includes or imports, with positions.
  const std::vector<std::pair<std::string, uint32_t>>& references() const { return references_; }
  bool hasExtends() const { return hasExtends_; }

  /// 1-based line and column (in characters) of byte offset `pos`.
  std::pair<int, int> lineColumn(uint32_t pos) const;
  TemplateError error(uint32_t pos, std::string message) const;
  std::vector<std::unique_ptr<SkipMask>>& skipMasks() const { return skipMasks_; }
  /// A hint into skipMasks() by the policy's `only` block (index + 1, or 0).
  uint16_t& skipMaskHint(const std::string* only) const {
    return skipMaskHints_[(reinterpret_cast<uintptr_t>(only) >> 4) % kSkipMaskHints];
  }

 private:
  std::string name_;
  std::string origin_;
  std::string source_;
  Arena arena_;
  Body body_;
  FrameLayout rootFrame_;
  std::vector<BlockStmt*> blocks_;
  std::vector<std::pair<std::string, uint32_t>> references_;
  bool hasExtends_ = false;
  static constexpr size_t kSkipMaskHints = 61;
  mutable std::vector<std::unique_ptr<SkipMask>> skipMasks_;
  mutable uint16_t skipMaskHints_[kSkipMaskHints] = {};
};

}  // namespace smachac::tmpl
