// Writes a compiled template as its image (image_format.h): what the build stores for each
// built-in template so that a compile loads it instead of parsing (image_reader.h).
// Rules: the template's deferred macros are completed first (they are stored as records read
// on first call, the others inline); the same template gives the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "backends/tmpl/template.h"

namespace smachac::tmpl {

/// The image of `tmpl` (a template compiled from its source, not from an image).
std::vector<uint8_t> writeTemplateImage(const Template& tmpl);

}  // namespace smachac::tmpl
