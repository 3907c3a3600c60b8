// The meta blocks of the built-in templates, read and parsed when the compiler is built
// (tools/cmake/meta_table_gen.cpp writes the table), so that a compile looks them up instead
// of parsing each template and its YAML. A template whose meta block uses template syntax has
// no row: it is read at run time. backends/meta/template_meta_lookup.h decides when a row applies
// (the template must come from the built-in sets, not from an -I directory).
#pragma once

#include <span>
#include <string_view>

namespace smachac::templates {

struct BuiltinMetaVariable {
  std::string_view name;
  std::span<const std::string_view> types;
  bool required;
  int alternative_group;
};

struct BuiltinMeta {
  std::string_view path;  ///< relative to templates/, e.g. "smach/Base.tpl.py"
  bool parsed;            ///< false: no meta block, or one that is not YAML of the right shape
  std::span<const BuiltinMetaVariable> variables;
  std::span<const std::string_view> outcomes;
};

/// Every precompiled template, sorted by path.
std::span<const BuiltinMeta> builtinMetas();

/// The row of the built-in template at `path`, or nullptr when the build did not precompile it.
const BuiltinMeta* findBuiltinMeta(std::string_view path);

}  // namespace smachac::templates
