// The SMACH target (`-target=smach`): one Python file, rendered by SMACHA's generator from the
// built-in template sets `smach/` (core) then `smach_ros/` (ROS), after the -I directories.
// -c keeps the templates' comment blocks (and turns on the built-in templates' comments), -i
// the introspection server blocks of ROS bases.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/targets.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends::smach {

std::optional<std::vector<OutputFile>> emitSmach(ir::Module&& module, EmitContext& context);

/// The template search path of the target: -I directories, then the built-in sets.
generator::TemplatePath templatePath(const std::vector<std::string>& template_dirs);

/// A template environment over `path` with the target's filter, test and global; the
/// `forced_string` test asks `converter`, which must outlive the environment's renders.
std::unique_ptr<tmpl::Environment> makeEnvironment(const generator::TemplatePath& path,
                                                   const generator::ValueConverter& converter,
                                                   bool include_comments);

}  // namespace smachac::backends::smach
