// `smachac help` without a template: the templates a target finds (-I directories, then its
// built-in sets), one per line with the first sentence of its meta description.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "backends/generator/template_catalog.h"
#include "backends/generator/template_values.h"
#include "backends/tmpl/environment.h"
#include "tools/smachac/help_style.h"

namespace smachac::driver {

/// The search path of `target` (smach, cpp or flexbe) with the -I directories first.
generator::TemplatePath targetTemplatePath(const std::string& target,
                                           const std::vector<std::string>& template_dirs);

/// A template environment for reading `target`'s templates (its filters registered).
std::unique_ptr<tmpl::Environment> targetEnvironment(const std::string& target,
                                                     const generator::TemplatePath& path,
                                                     const generator::ValueConverter& converter);

/// Prints `<target> templates:` and one line per template: its name and summary.
void listTemplates(std::ostream& out, const std::string& target,
                   const std::vector<std::string>& template_dirs, const HelpStyle& style);

}  // namespace smachac::driver
