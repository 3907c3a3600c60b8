// The script's behavior and its embedded behaviors, rendered one by one.
#include "backends/flexbe/behavior_writer.h"

#include <filesystem>
#include <map>
#include <set>

#include "backends/flexbe/behavior_parameters.h"
#include "backends/flexbe/embedded_behaviors.h"
#include "backends/flexbe/explicit_transitions.h"
#include "backends/meta/template_meta.h"

namespace smachac::backends::flexbe {
namespace {

/// One rendered behavior made of a sub-script.
struct Variant {
  std::string name;
  std::vector<BehaviorParameter> parameters;
  std::string code;
};

std::vector<std::string> parameterNames(const std::vector<BehaviorParameter>& parameters) {
  std::vector<std::string> names;
  for (const BehaviorParameter& p : parameters) names.push_back(p.name.text);
  return names;
}

void collectReferences(const ir::Value& value, std::set<uint32_t>& refs) {
  if (value.behavior_param != 0) refs.insert(value.behavior_param);
  if (value.isList()) {
    for (const ir::Value& item : value.asList()) collectReferences(item, refs);
  } else if (value.isMap()) {
    for (const ir::MapEntry& entry : value.asMap()) collectReferences(entry.value, refs);
  }
}

/// The behavior parameter references that the values of the states below `root` hold.
std::set<uint32_t> referencesBelow(const ir::Module& module, ir::StateId root) {
  std::set<uint32_t> refs;
  std::vector<ir::StateId> stack(module.state(root).children);
  while (!stack.empty()) {
    const ir::State& state = module.state(stack.back());
    stack.pop_back();
    stack.insert(stack.end(), state.children.begin(), state.children.end());
    for (const auto* list : {&state.args, &state.userdata, &state.callbacks}) {
      for (const ir::Argument& a : *list) collectReferences(a.value, refs);
    }
  }
  return refs;
}

/// A file stem as a behavior name: ASCII letters, digits and `_`, starting with a letter.
std::string behaviorNameOf(const std::string& path) {
  std::string name;
  for (char c : std::filesystem::path(path).stem().string()) {
    bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    name += word ? static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c) : '_';
  }
  if (name.empty() || !(name[0] >= 'a' && name[0] <= 'z')) name = "behavior_" + name;
  return name;
}

/// The outcomes of a template's meta block, read once per template name.
class MetaOutcomes {
 public:
  explicit MetaOutcomes(tmpl::Environment& env) : env_(env) {}

  std::vector<std::string> operator()(const std::string& name) {
    auto it = cache_.find(name);
    if (it == cache_.end()) it = cache_.emplace(name, read(name)).first;
    return it->second;
  }

 private:
  std::vector<std::string> read(const std::string& name) {
    try {
      std::optional<std::string> file = env_.resolveScriptTemplate(name);
      std::optional<std::string> meta = file ? env_.metaBlock(*file) : std::nullopt;
      std::optional<TemplateMeta> parsed = meta ? parseTemplateMeta(*meta) : std::nullopt;
      if (parsed) return parsed->outcomes;
    } catch (const std::exception&) {
      // a template that cannot be read is reported when it is rendered
    }
    return {};
  }

  tmpl::Environment& env_;
  std::map<std::string, std::vector<std::string>> cache_;
};

class Writer {
 public:
  Writer(const ir::Module& module, generator::GeneratorContext& context)
      : module_(withExplicitTransitions(module, MetaOutcomes(context.env), context.diags)),
        context_(context) {}

  std::optional<std::vector<std::string>> run() {
    ir::StateId root = module_.root();
    const ir::State& main = module_.state(root);
    main_name_ = main.name.text;
    used_names_.insert(behaviorNameOf(main_name_));
    std::vector<BehaviorParameter> parameters = scriptParameters(main, context_.diags);
    std::vector<ir::StateId> embedded = embeddedStates(module_, context_.diags);
    std::set<ir::StateId> roots(embedded.begin(), embedded.end());
    for (ir::StateId state : embedded) {
      if (failed_) return std::nullopt;  // one failed render is enough to report
      embed(state, behaviorPath(module_, state, roots));
    }
    std::optional<std::string> code = render(root, root, parameters);
    if (!code || failed_) return std::nullopt;
    codes_.insert(codes_.begin(), std::move(*code));
    return std::move(codes_);
  }

 private:
  /// Renders the behavior made of included `state` (or reuses an equal one) and turns
  /// `state` into the leaf that uses it.
  void embed(ir::StateId state, const std::string& id) {
    const ir::State& included = module_.state(state);
    const ir::Inclusion& inclusion = included.included_from.front();
    ir::Value instance = included.params ? *included.params : ir::Value::map({});
    std::vector<BehaviorParameter> own = usedParameters(
        state, behaviorParameters(instance, inclusion.script_params), inclusion.script_params);
    std::vector<Variant>& variants = groups_[inclusion.file];
    std::string base_name = behaviorNameOf(context_.sources.path(inclusion.file));
    ir::Name base_template =
        module_.state(module_.root()).template_name.value_or(ir::Name{"Base", included.loc});
    ir::StateId root = detachBehavior(module_, state, base_name, base_template);
    const Variant* chosen = nullptr;
    for (const Variant& variant : variants) {
      if (parameterNames(variant.parameters) != parameterNames(own)) continue;
      module_.state(root).name.text = variant.name;
      std::optional<std::string> code = render(root, state, variant.parameters);
      if (code && *code == variant.code) chosen = &variant;
      if (chosen || !code) break;
    }
    if (!chosen) chosen = addVariant(variants, root, state, base_name, std::move(own));
    if (!chosen) return;
    useBehavior(module_, state, chosen->name, id, passedParameters(instance, chosen->parameters));
  }

  /// The parameters the sub-script declares, and those of the others that a state uses.
  std::vector<BehaviorParameter> usedParameters(ir::StateId state,
                                                std::vector<BehaviorParameter> parameters,
                                                const std::optional<ir::Value>& declared) {
    std::set<uint32_t> used = referencesBelow(module_, state);
    std::erase_if(parameters, [&](const BehaviorParameter& p) {
      return !(declared && declared->find(p.name.text)) &&
             !used.count(module_.findBehaviorParam(state, p.name.text));
    });
    return parameters;
  }

  const Variant* addVariant(std::vector<Variant>& variants, ir::StateId root, ir::StateId scope,
                            const std::string& base_name,
                            std::vector<BehaviorParameter> parameters) {
    std::string name = uniqueName(base_name);
    module_.state(root).name.text = name;
    std::optional<std::string> code = render(root, scope, parameters);
    if (!code) return nullptr;
    codes_.push_back(*code);
    variants.push_back({name, std::move(parameters), std::move(*code)});
    return &variants.back();
  }

  std::string uniqueName(const std::string& base) {
    std::string name = base;
    for (int n = 2; used_names_.count(name); ++n) name = base + "_" + std::to_string(n);
    used_names_.insert(name);
    return name;
  }

  /// The parameters an instance passes: those whose value is not the default, and those
  /// that are parameters of the including behavior (written `self.<name>`).
  static ir::Value passedParameters(const ir::Value& instance,
                                    const std::vector<BehaviorParameter>& parameters) {
    ir::Value passed = ir::Value::map({});
    for (const BehaviorParameter& p : parameters) {
      const ir::Value* value = instance.find(p.name.text);
      if (!value || (value->behavior_param == 0 && sameValue(*value, p.default_value))) continue;
      passed.asMap().push_back({p.name.text, p.name.loc, *value});
    }
    return passed;
  }

  /// The generator's output for the behavior whose Base root is `root`, made of `scope`
  /// (the state whose params its parameters are).
  std::optional<std::string> render(ir::StateId root, ir::StateId scope,
                                    const std::vector<BehaviorParameter>& parameters) {
    setGlobals(root, parameters);
    context_.converter.referToBehaviorParams(parameterReferences(module_, scope, parameters));
    ir::StateId main = module_.root();
    module_.setRoot(root);
    std::optional<std::string> code = generator::generate(module_, context_);
    module_.setRoot(main);
    context_.converter.referToBehaviorParams({});
    if (!code) failed_ = true;
    return code;
  }

  void setGlobals(ir::StateId root, const std::vector<BehaviorParameter>& parameters) {
    std::vector<tmpl::Value> declared;
    for (const BehaviorParameter& p : parameters) {
      declared.push_back(entry("name", tmpl::Value::string(p.name.text), "value",
                               context_.converter.convert(p.default_value)));
    }
    std::vector<tmpl::Value> contained;
    for (const auto& [name, id] : usedBehaviors(module_, root)) {
      contained.push_back(entry("name", tmpl::Value::string(name), "id", tmpl::Value::string(id)));
    }
    context_.env.addGlobal("behavior_parameters", tmpl::Value::newList(std::move(declared)));
    context_.env.addGlobal("contained_behaviors", tmpl::Value::newList(std::move(contained)));
    context_.env.addGlobal("main_behavior", tmpl::Value::string(main_name_));
  }

  static tmpl::Value entry(std::string_view k1, tmpl::Value v1, std::string_view k2,
                           tmpl::Value v2) {
    tmpl::Value dict = tmpl::Value::newDict();
    dict.dict().setString(k1, std::move(v1));
    dict.dict().setString(k2, std::move(v2));
    return dict;
  }

  ir::Module module_;
  generator::GeneratorContext& context_;
  std::string main_name_;
  std::set<std::string> used_names_;
  std::map<uint32_t, std::vector<Variant>> groups_;
  std::vector<std::string> codes_;
  bool failed_ = false;
};

}  // namespace

std::optional<std::vector<std::string>> writeBehaviors(const ir::Module& module,
                                                       generator::GeneratorContext& context) {
  return Writer(module, context).run();
}

}  // namespace smachac::backends::flexbe
