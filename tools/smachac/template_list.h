// `smachac help` without a template: the templates a target finds (-I directories, then its
// built-in sets), one per line with the first sentence of its meta description.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "tools/smachac/help_style.h"

namespace smachac::driver {

/// Prints `<target> templates:` and one line per template: its name and summary.
void listTemplates(std::ostream& out, const std::string& target,
                   const std::vector<std::string>& template_dirs, const HelpStyle& style);

}  // namespace smachac::driver
