// Loads a template's image (image_format.h) into its arena: the nodes built directly, names
// interned as the parser interns them, filters and tests found by name in the registry.
// Rules: `open` refuses an image that does not fit its source or names a filter or test the
// registry lacks, and `readTemplate` one whose bytes do not read as a template; the caller then
// compiles the source. A deferred macro's record is read on its first call (`readMacro`).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/ast/ast.h"
#include "backends/tmpl/filters/builtins.h"

namespace smachac::tmpl {

/// A top-level macro whose signature and body wait in the image: where its record begins.
struct ImageMacro {
  MacroStmt* macro;
  size_t offset;
};

/// What an image holds of a template besides its arena's nodes.
struct ImageTemplate {
  Body body;
  FrameLayout root_frame;
  std::vector<BlockStmt*> blocks;
  std::vector<std::pair<std::string, uint32_t>> references;
  bool has_extends = false;
  bool names_templates = false;
  std::vector<ImageMacro> deferred;
};

class ImageReader {
 public:
  /// The reader of `image` for `source` (the template's normalised text); null if the image
  /// does not fit it or `registry` lacks one of its filters or tests. The image and the
  /// registry must outlive the reader.
  static std::unique_ptr<ImageReader> open(std::span<const uint8_t> image, std::string_view source,
                                           const Registry& registry);

  /// The template, its nodes made in `arena`; false if the bytes do not read as one.
  bool readTemplate(Arena& arena, ImageTemplate& out);
  /// Fills a deferred macro from its record; raises Fault if the record does not read.
  void readMacro(const ImageMacro& deferred, Arena& arena);

  ImageReader(std::span<const uint8_t> image, std::string_view source);

 private:
  bool readTables(const Registry& registry);

  std::span<const uint8_t> image_;
  std::string_view source_;
  size_t content_ = 0;  // where the template's fields begin
  std::vector<std::string_view> strings_;
  std::vector<const std::string*> names_;  // interned on first use, by string index
  std::vector<std::pair<const std::string*, const FilterDef*>> filters_;
  std::vector<std::pair<const std::string*, const TestDef*>> tests_;

  friend class ImageCursor;
};

}  // namespace smachac::tmpl
