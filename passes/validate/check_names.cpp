// check-names: the names of states and keys.
//   * duplicate-state-name      two children of one container have the same name (SMACH keeps
//                               one state per label; transitions could not tell them apart)
//   * state-named-like-outcome  a state of a StateMachine (or the root) is named like an outcome
//                               of the container: transitions to that name reach the state
//   * duplicate-list-entry      a name listed twice in `outcomes`, `input_keys`, `output_keys`
//   * invalid-identifier        for code targets (ir/support/identifiers.h), names that
//                               become identifiers: the script name (the variable
//                               `<name lower>`), container names (`sm_<name lower>`), and
//                               userdata keys (`ud.<key>`; entries of `userdata` are also
//                               written lower-cased) in `userdata`, `input_keys`, `output_keys`,
//                               `remapping` (both sides) and `callbacks`; for C++, a
//                               callback given as a plain string names a function: it must
//                               be an identifier, `::`-qualified or not; the base
//                               template's `function_name` argument (the generated main
//                               function, lower-cased for Python) too
//   * template-argument-not-identifier
//                               for code targets, a template argument key that no template
//                               can refer to
#include <fmt/core.h>

#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "ir/support/identifiers.h"
#include "passes/analysis/outcomes.h"
#include "passes/validate/checks.h"

namespace smachac::passes {
namespace {

class NameChecker {
 public:
  NameChecker(const ir::Module& module, PassContext& context)
      : module_(module), diags_(context.diags), rules_(identifierRules(context.target)) {}

  void run() {
    for (ir::StateId id : module_.preorder()) {
      const ir::State& state = module_.state(id);
      if (ir::isContainer(state.kind)) checkChildren(state);
      checkList(state, state.outcomes, "outcomes");
      checkList(state, state.input_keys, "input_keys");
      checkList(state, state.output_keys, "output_keys");
      if (rules_ != IdentifierRules::None) checkIdentifiers(state);
    }
  }

 private:
  void checkChildren(const ir::State& container) {
    std::unordered_map<std::string_view, const ir::State*> seen;
    seen.reserve(container.children.size());
    NameSet outcomes = isSequential(container.kind) ? nameSet(container.outcomes) : NameSet();
    for (ir::StateId id : container.children) {
      const ir::State& child = module_.state(id);
      auto [it, inserted] = seen.emplace(child.name.text, &child);
      if (!inserted) {
        diags_.emit<DiagKind::DuplicateStateName>(child.name.loc, container.name.text,
                                                  child.name.text);
        diags_.note<DiagNoteKind::FirstStateNamedSo>(it->second->name.loc);
      }
      if (outcomes.contains(child.name.text)) {
        diags_.emit<DiagKind::StateNamedLikeOutcome>(child.name.loc, child.name.text,
                                                     container.name.text, child.name.text);
      }
    }
  }

  void checkList(const ir::State& state, const std::vector<ir::Name>& names,
                 std::string_view field) {
    if (names.size() < 2) return;
    constexpr size_t kLinearScanLimit = 16;  // short lists (the usual ones) need no hash set
    NameSet seen;
    for (size_t i = 0; i < names.size(); ++i) {
      const ir::Name& name = names[i];
      bool repeated = false;
      if (names.size() <= kLinearScanLimit) {
        for (size_t j = 0; j < i && !repeated; ++j) repeated = names[j].text == name.text;
      } else {
        repeated = !seen.insert(name.text).second;
      }
      if (repeated) {
        diags_.emit<DiagKind::DuplicateListEntry>(name.loc, name.text, field, state.name.text);
      }
    }
  }

  void checkIdentifiers(const ir::State& state) {
    if (state.kind == ir::StateKind::Base) {
      checkVariable("script name", state.name, asciiLower(state.name.text));
      checkMainFunctionName(state);
    } else if (ir::isContainer(state.kind)) {
      checkVariable("container name", state.name, "sm_" + asciiLower(state.name.text));
    }
    for (const ir::Argument& entry : state.userdata) {
      if (checkKey(entry.key) && rules_ == IdentifierRules::Python) {
        checkVariable("userdata key", entry.key, asciiLower(entry.key.text));
      }
    }
    for (const ir::Name& key : state.input_keys) checkKey(key);
    for (const ir::Name& key : state.output_keys) checkKey(key);
    for (const ir::Remap& remap : state.remapping) {
      checkKey(remap.key);
      checkKey(remap.parent_key);
    }
    for (const ir::Argument& callback : state.callbacks) {
      checkKey(callback.key);
      if (rules_ == IdentifierRules::Cpp) checkFunctionName(callback.value);
    }
    for (const ir::Argument& arg : state.args) checkTemplateArgument(state, arg.key);
  }

  /// A name that is used as it is; returns whether it is valid.
  bool checkKey(const ir::Name& key) {
    if (valid_keys_.contains(key.text)) return true;
    std::optional<std::string> problem = identifierProblem(key.text, rules_);
    if (problem) {
      diags_.emit<DiagKind::InvalidIdentifier>(key.loc, "userdata key", key.text, rulesName(rules_),
                                               "it " + *problem);
    } else {
      valid_keys_.insert(key.text);
    }
    return !problem;
  }

  /// A name that becomes the identifier `variable`.
  void checkVariable(std::string_view what, const ir::Name& name, const std::string& variable) {
    checkVariable(what, name.text, name.loc, variable);
  }

  /// `text` (written at `loc`) that becomes the identifier `variable`.
  void checkVariable(std::string_view what, std::string_view text, SourceLoc loc,
                     const std::string& variable) {
    std::optional<std::string> problem = identifierProblem(variable, rules_);
    if (!problem) return;
    std::string reason = variable == text
                             ? "it " + *problem
                             : fmt::format("it becomes `{}`, which {}", variable, *problem);
    diags_.emit<DiagKind::InvalidIdentifier>(loc, what, text, rulesName(rules_), reason);
  }

  /// The base template's `function_name`: the name of the generated main function.
  void checkMainFunctionName(const ir::State& base) {
    for (const ir::Argument& arg : base.args) {
      if (arg.key.text != "function_name" || arg.value.kind() != ir::ValueKind::String) continue;
      const std::string& text = arg.value.asString();
      std::string variable = rules_ == IdentifierRules::Python ? asciiLower(text) : text;
      checkVariable("function name", text, arg.value.loc, variable);
    }
  }

  /// A callback written as a plain string: the C++ program calls the function of that name.
  void checkFunctionName(const ir::Value& value) {
    if (value.kind() != ir::ValueKind::String) return;
    std::string_view text = value.asString();
    std::string_view rest = text.starts_with("::") ? text.substr(2) : text;
    while (true) {
      size_t separator = rest.find("::");
      std::string_view part = rest.substr(0, separator);
      if (std::optional<std::string> problem = identifierProblem(part, rules_)) {
        std::string reason =
            part == text ? "it " + *problem : fmt::format("its part `{}` {}", part, *problem);
        diags_.emit<DiagKind::InvalidIdentifier>(value.loc, "callback function name", text,
                                                 rulesName(rules_), reason);
        return;
      }
      if (separator == std::string_view::npos) return;
      rest = rest.substr(separator + 2);
    }
  }

  void checkTemplateArgument(const ir::State& state, const ir::Name& key) {
    if (isAsciiIdentifier(key.text)) return;
    diags_.emit<DiagKind::TemplateArgumentNotIdentifier>(key.loc, key.text, state.name.text);
  }

  const ir::Module& module_;
  DiagnosticEmitter& diags_;
  IdentifierRules rules_;
  /// Keys found valid: a script names the same few keys in most of its states.
  std::unordered_set<std::string_view> valid_keys_;
};

}  // namespace

void checkNames(const ir::Module& module, PassContext& context) {
  NameChecker(module, context).run();
}

}  // namespace smachac::passes
