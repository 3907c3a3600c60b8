// Meta lookup: the precompiled table first, the engine and the YAML parser otherwise.
#include "backends/meta/template_meta_lookup.h"

#include "templates/builtin_meta.h"

namespace smachac::backends {
namespace {

TemplateMeta fromTable(const templates::BuiltinMeta& row) {
  TemplateMeta meta;
  for (const templates::BuiltinMetaVariable& v : row.variables) {
    meta.variables.push_back({std::string(v.name),
                              std::vector<std::string>(v.types.begin(), v.types.end()), v.required,
                              v.alternative_group});
  }
  meta.outcomes.assign(row.outcomes.begin(), row.outcomes.end());
  return meta;
}

}  // namespace

std::optional<std::optional<TemplateMeta>> precompiledTemplateMeta(
    const generator::TemplatePath& path, const std::string& name) {
  if (std::optional<std::string> builtin = generator::builtinTemplatePath(path, name)) {
    if (const templates::BuiltinMeta* row = templates::findBuiltinMeta(*builtin)) {
      return row->parsed ? std::optional<TemplateMeta>(fromTable(*row)) : std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<TemplateMeta> lookUpTemplateMeta(tmpl::Environment& env,
                                               const generator::TemplatePath& path,
                                               const std::string& name) {
  if (std::optional<std::optional<TemplateMeta>> table = precompiledTemplateMeta(path, name)) {
    return *table;
  }
  try {
    std::optional<std::string> text = env.metaBlock(name);
    return text ? parseTemplateMeta(*text) : std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;  // a broken meta block is reported when the template is rendered
  }
}

}  // namespace smachac::backends
