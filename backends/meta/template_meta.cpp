// Meta block parsing.
#include "backends/meta/template_meta.h"

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/value_convert.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::backends {
namespace {

using tmpl::Value;

std::vector<std::string> typesOf(const Value& spec) {
  std::vector<std::string> types;
  const Value* type = spec.isDict() ? spec.dict().findString("type") : nullptr;
  if (!type) return types;
  if (type->isListOrTuple()) {
    for (const Value& t : type->list().items()) types.push_back(tmpl::str(t));
  } else {
    types.push_back(tmpl::str(*type));
  }
  return types;
}

class MetaReader {
 public:
  void entries(const Value& list) {
    if (!list.isListOrTuple()) return;
    for (const Value& entry : list.list().items()) this->entry(entry);
  }

  TemplateMeta meta;

 private:
  /// `{var: spec}` adds a variable; `{heading: [...]}` recurses into the group.
  void dictEntry(const Value& dict, bool required, int group) {
    for (const auto& [key, spec] : dict.dict().entries()) {
      if (spec.isListOrTuple()) {
        entries(spec);
        continue;
      }
      meta.variables.push_back({tmpl::str(key), typesOf(spec), required, group});
    }
  }

  void entry(const Value& e) {
    if (e.isDict()) {
      dictEntry(e, true, -1);
    } else if (e.isListOrTuple() && e.list().items().size() == 1) {
      const Value& only = e.list().items().front();
      if (only.isDict()) dictEntry(only, false, -1);
    } else if (e.isListOrTuple()) {
      int group = next_group_++;
      for (const Value& option : e.list().items()) {
        if (option.isDict()) dictEntry(option, false, group);
      }
    }
  }

  int next_group_ = 0;
};

}  // namespace

std::optional<TemplateMeta> parseTemplateMeta(std::string_view text) {
  try {
    Value root = tmpl::parseYaml(text, "meta");
    if (!root.isDict()) return std::nullopt;
    MetaReader reader;
    if (const Value* variables = root.dict().findString("variables")) reader.entries(*variables);
    if (const Value* outcomes = root.dict().findString("outcomes");
        outcomes && outcomes->isList()) {
      for (const Value& outcome : outcomes->list().items()) {
        if (outcome.isString()) reader.meta.outcomes.push_back(outcome.s());
      }
    }
    return std::move(reader.meta);
  } catch (const tmpl::TemplateError&) {
    return std::nullopt;
  }
}

}  // namespace smachac::backends
