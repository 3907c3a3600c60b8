// Where a compile gets a template's meta (template_meta.h) from: the table the build
// precompiled (templates/builtin_meta.h) when the template comes from the built-in sets,
// otherwise its meta block read through the engine and parsed. Both give the same result:
// tests/unit/backends/meta checks the table against the run-time parse.
#pragma once

#include <optional>
#include <string>

#include "backends/generator/template_catalog.h"
#include "backends/meta/template_meta.h"
#include "backends/tmpl/environment.h"

namespace smachac::backends {

/// The meta of the template with exactly this name on `path` (whose templates `env` loads);
/// nullopt when it has no meta block, or one that cannot be read or parsed.
std::optional<TemplateMeta> lookUpTemplateMeta(tmpl::Environment& env,
                                               const generator::TemplatePath& path,
                                               const std::string& name);

/// The table's answer for a built-in template (the same as lookUpTemplateMeta's), or nullopt
/// when the table has none and the engine must read the template.
std::optional<std::optional<TemplateMeta>> precompiledTemplateMeta(
    const generator::TemplatePath& path, const std::string& name);

}  // namespace smachac::backends
