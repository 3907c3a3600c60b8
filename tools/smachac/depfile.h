// `--depfile=PATH`: a Make-style dependency file for build systems (CMake's DEPFILE, Ninja,
// Make): the output depends on the script, every sub-script it read, and every file in the -I
// template directories (a superset of the templates read, so that editing one reruns
// smachac). Paths are absolute; spaces, `#` and `$` are escaped as Make and Ninja expect.
#pragma once

#include <string>
#include <vector>

#include "ir/module.h"
#include "ir/support/source_manager.h"

namespace smachac::driver {

/// The depfile's text: `<output>: <dependency> ...`, one dependency per continued line.
std::string depfileText(const std::string& output, const ir::Module& module,
                        const SourceManager& sources,
                        const std::vector<std::string>& template_dirs);

}  // namespace smachac::driver
