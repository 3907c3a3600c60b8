// Template existence, variables and literal types, from meta blocks.
#include "backends/meta/template_check.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>

#include "backends/cpp/cpp_extensions.h"
#include "backends/generator/template_catalog.h"
#include "backends/meta/template_meta.h"
#include "backends/meta/template_meta_lookup.h"
#include "backends/smach/python_extensions.h"
#include "backends/smach/smach_lint.h"
#include "backends/tmpl/environment.h"
#include "backends/tmpl/error.h"
#include "backends/tmpl/loader.h"
#include "ir/support/suggest.h"
#include "ir/type.h"
#include "templates/builtin_templates.h"

namespace smachac::backends {
namespace {

std::vector<std::string> builtinSets(std::string_view target) {
  if (target == "smach") return {"smach/", "smach_ros/"};
  if (target == "flexbe") return {"flexbe/"};
  if (target == "cpp") return {"cpp/"};
  return {};
}

/// Keys every template gets from the generator or the IR's structure.
bool isImplicit(std::string_view key) {
  return key == "name" || key == "class_name" || key == "uuid" || key == "sm_name" ||
         key == "autonomy";  // FlexBE autonomy levels, read by the flexbe target
}

/// Whether the script gives `s` the variable `key` (a state field or a script key): asked per
/// template variable, without collecting the state's keys first (a big script has many states).
bool givesKey(const ir::State& s, std::string_view key) {
  if (key == "outcomes") return !s.outcomes.empty();
  if (key == "input_keys") return !s.input_keys.empty();
  if (key == "output_keys") return !s.output_keys.empty();
  if (key == "transitions") return !s.transitions.empty();
  if (key == "remapping") return !s.remapping.empty();
  if (key == "userdata") return !s.userdata.empty();
  if (key == "params") return static_cast<bool>(s.params);
  if (key == "callbacks") return !s.callbacks.empty();
  if (key == "outcome_map") return !s.outcome_map.empty();
  if (key == "default_outcome") return static_cast<bool>(s.default_outcome);
  return std::any_of(s.args.begin(), s.args.end(),
                     [&](const ir::Argument& a) { return a.key.text == key; });
}

/// Keys that are not identifiers are reported by check-names already.
bool isIdentifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  for (char c : key) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

/// Whether a literal fits one declared type; unknown type names accept anything.
bool fits(const ir::Value& v, const std::string& type) {
  using K = ir::ValueKind;
  K k = v.kind();
  if (k == K::Expression || k == K::Null) return true;
  if (type == "str" || type == "string") return k == K::String;
  if (type == "int") return k == K::Int;
  if (type == "float" || type == "number") return k == K::Float || k == K::Int;
  if (type == "bool") return k == K::Bool;
  if (type.starts_with("list") || type.starts_with("tuple")) return k == K::List;
  if (type.starts_with("dict")) return k == K::Map;
  return true;
}

class Checker {
 public:
  Checker(std::string_view target, const std::vector<std::string>& dirs, DiagnosticEmitter& diags)
      : target_(target),
        path_{dirs, builtinSets(target), templates::builtinTemplates()},
        loader_(path_.dirs, path_.builtin_sets, path_.builtins),
        diags_(diags) {}

  void run(const ir::Module& m) {
    for (ir::StateId id : m.preorder()) check(m.state(id), id == m.root());
  }

 private:
  void check(const ir::State& s, bool root) {
    if (!s.template_name) return;
    const ir::Name& name = *s.template_name;
    const std::optional<std::string>& file = resolve(name.text);
    if (!file) {
      if (reported_.emplace(name.loc.file, name.loc.line, name.loc.column).second) {
        const std::optional<std::string>& match = closestTemplate(name.text);
        diags_.emit<DiagKind::UnknownTemplate>(name.loc, name.text, generator::describePath(path_),
                                               didYouMean(match));
        diags_.fixIt(match);
      }
      return;
    }
    if (root) return;  // the base template's variables are the script's own keys
    const std::optional<TemplateMeta>& meta = metaOf(*file);
    if (!meta) return;
    checkRequired(s, *meta);
    checkArguments(s, *meta);
  }

  /// The template file a script name resolves to, looked up once per name (a lookup lists
  /// the template folders).
  const std::optional<std::string>& resolve(const std::string& script_name) {
    auto it = resolved_.find(script_name);
    if (it == resolved_.end()) {
      it = resolved_.emplace(script_name, loader_.resolveScriptName(script_name)).first;
    }
    return it->second;
  }

  /// The suggestion for an unknown name, looked for once per name (it compares the name with
  /// every template's: thousands of states naming the same missing template took seconds).
  const std::optional<std::string>& closestTemplate(const std::string& script_name) {
    auto it = suggestions_.find(script_name);
    if (it == suggestions_.end()) {
      it = suggestions_.emplace(script_name, generator::closestTemplate(script_name, path_)).first;
    }
    return it->second;
  }

  const std::optional<TemplateMeta>& metaOf(const std::string& file) {
    auto it = metas_.find(file);
    if (it != metas_.end()) return it->second;
    return metas_.emplace(file, readMeta(file)).first->second;
  }

  // The precompiled table first; a template file whose text never says `meta` has no meta
  // block and is not compiled (one that did not compile would give none either).
  std::optional<TemplateMeta> readMeta(const std::string& file) {
    if (std::optional<std::optional<TemplateMeta>> table = precompiledTemplateMeta(path_, file)) {
      return *table;
    }
    try {
      std::optional<tmpl::TemplateSource> source = loader_.load(file);
      if (source && source->text().find("meta") == std::string_view::npos) return std::nullopt;
    } catch (const tmpl::Fault&) {  // an unreadable file: the lookup gives nullopt, as before
    }
    return lookUpTemplateMeta(environment(), path_, file);
  }

  /// The engine, made for the first template whose meta block must be read (resolving names
  /// and the precompiled metas need none), with the target's filters and tests: the engine
  /// checks every filter a template names.
  tmpl::Environment& environment() {
    if (env_) return *env_;
    env_ = std::make_unique<tmpl::Environment>(path_.dirs, path_.builtin_sets, path_.builtins);
    if (target_ == "cpp") {
      cpp::registerCppExtensions(*env_, converter_, false);
    } else {
      smach::registerPythonExtensions(*env_, converter_, false);
    }
    return *env_;
  }

  void checkRequired(const ir::State& s, const TemplateMeta& meta) {
    std::map<int, std::vector<std::string>> groups;
    for (const TemplateVariable& v : meta.variables) {
      if (v.alternative_group >= 0) groups[v.alternative_group].push_back(v.name);
      if (!v.required || isImplicit(v.name) || givesKey(s, v.name)) continue;
      diags_.emit<DiagKind::MissingTemplateVariable>(s.name.loc, s.name.text, s.template_name->text,
                                                     "`" + v.name + "`");
    }
    for (const auto& [group, names] : groups) {
      bool any = false;
      for (const std::string& n : names) any = any || givesKey(s, n);
      if (any) continue;
      std::string options;
      for (const std::string& n : names) options += (options.empty() ? "`" : " or `") + n + "`";
      diags_.emit<DiagKind::MissingTemplateVariable>(s.name.loc, s.name.text, s.template_name->text,
                                                     "one of " + options);
    }
  }

  void checkArguments(const ir::State& s, const TemplateMeta& meta) {
    for (const ir::Argument& a : s.args) {
      const TemplateVariable* var = find(meta, a.key.text);
      if (!var) {
        if (isImplicit(a.key.text) || !isIdentifier(a.key.text)) continue;
        std::vector<std::string> declared;
        for (const TemplateVariable& v : meta.variables) declared.push_back(v.name);
        std::optional<std::string> match = closestMatch(a.key.text, declared);
        diags_.emit<DiagKind::UnknownTemplateVariable>(a.key.loc, a.key.text, s.template_name->text,
                                                       didYouMean(match));
        diags_.fixIt(match);
        continue;
      }
      checkType(s, a, *var);
    }
  }

  void checkType(const ir::State& s, const ir::Argument& a, const TemplateVariable& var) {
    if (var.types.empty()) return;
    for (const std::string& t : var.types) {
      if (fits(a.value, t)) return;
    }
    std::string declared;
    for (const std::string& t : var.types) declared += (declared.empty() ? "" : " or ") + t;
    diags_.emit<DiagKind::TemplateVariableType>(a.value.loc, a.key.text, s.name.text,
                                                ir::Type::ofValue(a.value).str(),
                                                s.template_name->text, declared);
  }

  static const TemplateVariable* find(const TemplateMeta& meta, const std::string& name) {
    for (const TemplateVariable& v : meta.variables) {
      if (v.name == name) return &v;
    }
    return nullptr;
  }

  std::string target_;
  generator::TemplatePath path_;
  tmpl::Loader loader_;
  generator::ValueConverter converter_;
  std::unique_ptr<tmpl::Environment> env_;
  DiagnosticEmitter& diags_;
  std::map<std::string, std::optional<TemplateMeta>> metas_;
  std::unordered_map<std::string, std::optional<std::string>> resolved_;
  std::unordered_map<std::string, std::optional<std::string>> suggestions_;
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> reported_;
};

}  // namespace

bool checkTemplates(const ir::Module& module, std::string_view target,
                    const std::vector<std::string>& template_dirs, DiagnosticEmitter& diags) {
  if (builtinSets(target).empty()) return true;
  size_t errors_before = diags.errorCount();
  Checker(target, template_dirs, diags).run(module);
  if (target == "smach") smach::checkSmachDivergences(module, diags);
  return diags.errorCount() == errors_before;
}

}  // namespace smachac::backends
