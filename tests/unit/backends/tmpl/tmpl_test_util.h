// Helpers for the template engine's unit tests: render a template given as a string, or
// capture the error it raises.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "backends/tmpl/environment.h"
#include "backends/tmpl/values/value_convert.h"

namespace smachac::tmpl::testing {

inline const std::vector<EmbeddedFile> kNoBuiltins;

/// An environment holding `templates` (name, source) in memory.
inline std::unique_ptr<Environment> makeEnv(
    const std::vector<std::pair<std::string, std::string>>& templates) {
  auto env = std::make_unique<Environment>(std::vector<std::string>{}, std::vector<std::string>{},
                                           kNoBuiltins);
  for (const auto& [name, source] : templates) env->addTemplate(name, source);
  return env;
}

inline Value context(const std::string& yaml) {
  Value v = parseYaml(yaml, "context");
  return v.isNone() ? Value::newDict() : v;
}

inline std::string render(const std::string& source, const std::string& yaml = "{}") {
  return makeEnv({{"t", source}})->render("t", context(yaml));
}

/// The error `source` raises, as "file:line:col: message", or "no error".
inline std::string renderError(const std::string& source, const std::string& yaml = "{}") {
  try {
    render(source, yaml);
  } catch (const TemplateError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace smachac::tmpl::testing
