// Settings from JSON, and what the checks make of them.
#include "lsp/settings.h"

#include <fmt/core.h>

#include "backends/targets.h"

namespace smachac::lsp {
namespace {

std::optional<std::string> readStrings(const Json& json, const char* key,
                                       std::vector<std::string>& out) {
  if (!json.contains(key)) return std::nullopt;
  const Json& value = json[key];
  if (!value.is_array()) return fmt::format("setting `{}` must be a list of strings", key);
  std::vector<std::string> strings;
  for (const Json& item : value) {
    if (!item.is_string()) return fmt::format("setting `{}` must be a list of strings", key);
    strings.push_back(item.get<std::string>());
  }
  out = std::move(strings);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> applySettings(Settings& settings, const Json& json) {
  if (json.is_null()) return std::nullopt;
  if (!json.is_object()) return "the settings must be an object";
  Settings updated = settings;
  if (json.contains("target")) {
    if (!json["target"].is_string()) return "setting `target` must be a string";
    updated.target = json["target"].get<std::string>();
  }
  for (auto [key, field] : {std::pair{"templateDirs", &updated.template_dirs},
                            std::pair{"scriptDirs", &updated.script_dirs},
                            std::pair{"warnings", &updated.warning_flags}}) {
    if (std::optional<std::string> error = readStrings(json, key, *field)) return error;
  }
  if (std::optional<std::string> error = validateSettings(updated)) return error;
  settings = std::move(updated);
  return std::nullopt;
}

std::optional<std::string> validateSettings(const Settings& settings) {
  if (!backends::findTarget(settings.target)) {
    return fmt::format("unknown target `{}`", settings.target);
  }
  WarningOptions warnings;
  for (const std::string& flag : settings.warning_flags) {
    if (std::optional<std::string> error = warnings.apply(flag)) return error;
  }
  return std::nullopt;
}

WarningOptions warningOptions(const Settings& settings) {
  WarningOptions warnings;
  for (const std::string& flag : settings.warning_flags) warnings.apply(flag);
  return warnings;
}

checker::CheckOptions checkOptions(const Settings& settings) {
  checker::CheckOptions options;
  options.target = settings.target;
  options.template_dirs = settings.template_dirs;
  options.script_dirs = settings.script_dirs;
  options.sub_script_alone = true;
  options.keep_module_on_error = true;
  return options;
}

}  // namespace smachac::lsp
