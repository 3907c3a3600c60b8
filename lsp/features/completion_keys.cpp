// State and root keys.
#include "lsp/features/completion_keys.h"

#include <array>
#include <string_view>
#include <utility>

namespace smachac::lsp {
namespace {

using KeyDoc = std::pair<std::string_view, std::string_view>;

constexpr std::array<KeyDoc, 13> kCoreKeys = {{
    {"template", "The template the state is generated from."},
    {"script", "A sub-script to include as this state (its name, without `.yml`)."},
    {"outcomes", "The outcomes the state can end with."},
    {"input_keys", "The userdata keys the state reads."},
    {"output_keys", "The userdata keys the state writes."},
    {"transitions", "The sibling state or container outcome each outcome leads to."},
    {"remapping", "The container's userdata key for each of the state's keys."},
    {"userdata", "Userdata values, by key, set before the state runs."},
    {"params", "Values that lookups (`[params, x]`) in this state and inside it read."},
    {"callbacks", "Functions that compute userdata values, by output key."},
    {"outcome_map", "Concurrence: for each outcome, the outcome each listed child must end with."},
    {"default_outcome", "Concurrence: the outcome when no `outcome_map` entry holds."},
    {"states", "The states inside this container, in order; the first one starts."},
}};

constexpr std::array<KeyDoc, 11> kRootKeys = {{
    {"name", "The script's name."},
    {"template", "The base template the script is generated from (e.g. `Base`)."},
    {"outcomes", "The outcomes of the script's state machine."},
    {"states", "The script's states, in order; the first one starts."},
    {"userdata", "Userdata values of the script's state machine, by key."},
    {"params", "Values that lookups (`[params, x]`) in the states read."},
    {"manifest", "The ROS manifest (package) to load."},
    {"node_name", "The ROS node's name."},
    {"function_name", "The name of the generated main function."},
    {"import_modules", "Modules the script's code imports."},
    {"from_imports", "Names the script's code imports, by module."},
}};

bool isGeneratorVariable(std::string_view name) {
  return name == "name" || name == "class_name" || name == "uuid" || name == "sm_name" ||
         name == "autonomy";
}

bool isCoreKey(std::string_view name) {
  for (const KeyDoc& key : kCoreKeys) {
    if (key.first == name) return true;
  }
  return false;
}

std::string variableDetail(const TemplateVariableInfo& variable) {
  std::string detail = variable.type;
  if (variable.required) detail += detail.empty() ? "required" : ", required";
  if (variable.alternative) detail += detail.empty() ? "one of a choice" : ", one of a choice";
  return detail;
}

class KeyList {
 public:
  explicit KeyList(std::vector<ScopeName> written) : written_(std::move(written)) {}

  void add(std::string_view key, ItemKind kind, std::string detail, std::string_view doc) {
    if (contains(written_, key) || offered(key)) return;
    candidates_.push_back({std::string(key), kind, std::move(detail), std::string(doc)});
  }

  /// The template's variables; `required`: those that must be given (or chosen among).
  void addVariables(const TemplateInfo& info, bool required) {
    for (const TemplateVariableInfo& v : info.variables) {
      if ((v.required || v.alternative) != required || isGeneratorVariable(v.name)) continue;
      add(v.name, isCoreKey(v.name) ? ItemKind::Keyword : ItemKind::Property, variableDetail(v),
          v.description);
    }
  }

  std::vector<Candidate> take() { return std::move(candidates_); }

 private:
  bool offered(std::string_view key) const {
    for (const Candidate& c : candidates_) {
      if (c.label == key) return true;
    }
    return false;
  }

  std::vector<ScopeName> written_;
  std::vector<Candidate> candidates_;
};

/// The description of a root key: the base template's, else ours.
std::string_view rootKeyDoc(const KeyDoc& key, const std::optional<TemplateInfo>& info) {
  if (!info) return key.second;
  for (const TemplateVariableInfo& v : info->variables) {
    if (v.name == key.first && !v.description.empty()) return v.description;
  }
  return key.second;
}

}  // namespace

std::vector<Candidate> stateKeyCandidates(const ScopeState& state,
                                          const std::optional<TemplateInfo>& info) {
  std::vector<ScopeName> written = state.writtenKeys();
  if (contains(written, "template") || contains(written, "script")) {
    written.push_back({"template", {}});  // one of them makes the state: not the other
    written.push_back({"script", {}});
  }
  KeyList keys(written);
  keys.add(kCoreKeys[0].first, ItemKind::Keyword, "core key", kCoreKeys[0].second);
  keys.add(kCoreKeys[1].first, ItemKind::Keyword, "core key", kCoreKeys[1].second);
  if (info) {
    keys.addVariables(*info, true);
    keys.addVariables(*info, false);
  }
  for (const KeyDoc& key : kCoreKeys)
    keys.add(key.first, ItemKind::Keyword, "core key", key.second);
  return keys.take();
}

std::vector<Candidate> rootKeyCandidates(const ScopeState& root,
                                         const std::optional<TemplateInfo>& info) {
  KeyList keys(root.writtenKeys());
  for (const KeyDoc& key : kRootKeys) {
    keys.add(key.first, ItemKind::Keyword, "script key", rootKeyDoc(key, info));
  }
  return keys.take();
}

}  // namespace smachac::lsp
