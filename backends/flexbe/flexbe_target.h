// The FlexBE target (`-target=flexbe`): a FlexBE behavior rendered by SMACHA's generator from
// the built-in template set `flexbe/` (after the -I directories). The base template writes
// every file, each after a `#@smachac-file <path>` line: the behavior module `<name>_sm.py`,
// the generated EventState classes `<name>_states.py` (when leaf templates need them) and the
// manifest (XML for ROS 1, `<name>_manifest.py` for ROS 2; -flexbe-ros, default 2). The
// [MANUAL_*] sections of a behavior module already in the -o directory are kept.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/targets.h"

namespace smachac::backends::flexbe {

std::optional<std::vector<OutputFile>> emitFlexbe(ir::Module&& module, EmitContext& context);

/// The template search path of the target: -I directories, then the built-in `flexbe/` set.
generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs);

/// The files of the base template's output, split on its `#@smachac-file <path>` lines.
std::vector<OutputFile> splitFiles(std::string_view text);

}  // namespace smachac::backends::flexbe
