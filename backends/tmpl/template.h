// A compiled template: its normalised source (which the tokens and AST point into), the parsed
// statements with their scope layout, its blocks and the templates it references.
#pragma once

#include <deque>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/ast/ast.h"
#include "backends/tmpl/error.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/image/image_reader.h"
#include "backends/tmpl/parser/parser.h"

namespace smachac::tmpl {

/// The root code of a template as one skip policy runs it: the blocks it skips left out and
/// the texts that become adjacent merged (SMACHA renders each block with all the others
/// skipped, so most of a root is text between skipped blocks).
struct RootPlan {
  Body body;
  std::deque<std::string> texts;
  std::deque<TextStmt> merged;
  std::deque<Body> pieces;
};

/// Which blocks of a template one skip policy removes (a cache the renderer fills).
struct SkipMask {
  const std::string* only;
  const void* scope;
  std::vector<const std::string*> names;
  std::vector<char> skipped;       // by BlockStmt::index
  Value module;                    // the template's default module under this policy (imports)
  std::unique_ptr<RootPlan> plan;  // built on the first render under this policy
  /// The blocks not skipped, in order (what registerBlocks adds to a context).
  std::vector<const BlockStmt*> kept;
};

class Template {
 public:
  /// Compiles `source`; raises TemplateError (syntax error, unknown filter or test).
  /// `origin` is what errors name (a file path, or `<builtin>/smach/State.tpl.py`).
  /// A `builtin` template's text is the caller's built-in table, which outlives the template
  /// and is known to compile: it is read in place (unless normalising changes it, which
  /// copies it as any other source is), and top-level macros that allow it are parsed on
  /// their first call (parser/deferred_macro.cpp).
  /// `tokens`, if given, are the build's tokens of `source` (lexer/token_table.h), used
  /// instead of lexing it when they fit it. `registry` must outlive the template.
  /// `image`, if given, is the build's image of a built-in template (image/image_format.h),
  /// loaded instead of compiling when it fits the source and the registry.
  Template(std::string name, std::string origin, std::string_view source, const Registry& registry,
           bool builtin = false, std::span<const uint32_t> tokens = {},
           std::span<const uint8_t> image = {});
  Template(const Template&) = delete;
  Template& operator=(const Template&) = delete;

  const std::string& name() const { return name_; }
  const std::string& origin() const { return origin_; }
  std::string_view source() const { return source_; }
  const Body& body() const { return body_; }
  const FrameLayout& rootFrame() const { return root_frame_; }
  const std::vector<BlockStmt*>& blocks() const { return blocks_; }
  const BlockStmt* block(std::string_view name) const;
  /// String-literal names of the templates it extends, includes or imports, with positions.
  const std::vector<std::pair<std::string, uint32_t>>& references() const { return references_; }
  bool hasExtends() const { return has_extends_; }
  /// Whether it has an extends, include or import tag (by a literal name or not). One that has
  /// none renders and exports the same under every skip policy that skips its blocks alike.
  bool namesTemplates() const { return names_templates_; }
  /// Whether it was loaded from the build's image rather than compiled from its source.
  bool loadedFromImage() const { return from_image_; }

  /// 1-based line and column (in characters) of byte offset `pos`.
  std::pair<int, int> lineColumn(uint32_t pos) const;
  TemplateError error(uint32_t pos, std::string message) const;
  std::vector<std::unique_ptr<SkipMask>>& skipMasks() const { return skip_masks_; }
  /// Parses and analyses a deferred macro of this template (MacroStmt::deferred);
  /// raises TemplateError as the eager parse would have.
  void completeMacro(const MacroStmt& macro) const;

 private:
  /// Keeps the token stream for the deferred macros (`lexed` owns it unless it is empty).
  void keepTokens(std::span<const Token> stream, std::vector<Token> lexed) const;
  /// Takes the body, blocks, references and flags of a parsed or loaded template.
  template <typename Compiled>
  void adopt(Compiled& compiled);
  /// Takes the template from `image`; false (nothing taken) if the image does not fit.
  bool loadImage(std::span<const uint8_t> image);
  /// Completes `macro` from the image if it waits there.
  void completeFromImage(const MacroStmt& macro) const;

  std::string name_;
  std::string origin_;
  std::string owned_source_;  // the normalised source, unless it is read in place
  std::string_view source_;
  const Registry& registry_;
  mutable Arena arena_;  // deferred macro bodies are added on their first call
  Body body_;
  FrameLayout root_frame_;
  std::vector<BlockStmt*> blocks_;
  std::vector<std::pair<std::string, uint32_t>> references_;
  bool has_extends_ = false;
  bool names_templates_ = false;
  mutable std::vector<std::unique_ptr<SkipMask>> skip_masks_;
  // The tokens, kept while macros are deferred: the build's, read in place, or the lexer's.
  mutable std::span<const Token> tokens_;
  mutable std::vector<Token> lexed_tokens_;
  mutable std::vector<DeferredMacro> deferred_;
  // Loaded from an image: its reader, kept while macros wait in it.
  bool from_image_ = false;
  mutable std::unique_ptr<ImageReader> image_reader_;
  mutable std::vector<ImageMacro> image_deferred_;
};

}  // namespace smachac::tmpl
