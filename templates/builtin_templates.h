// The template sources of templates/, embedded into the binary at build time. Paths are
// relative to templates/, e.g. "smach/State.tpl.py".
#pragma once

#include <span>

#include "ir/support/embedded_file.h"

namespace smachac::templates {

std::span<const EmbeddedFile> builtinTemplates();

}  // namespace smachac::templates
