// Candidates by place: templates, sub-scripts, states and outcomes; keys are in
// completion_keys.cpp, userdata keys in completion_userdata.cpp.
#include "lsp/features/completion_candidates.h"

#include <algorithm>

#include "lsp/features/completion_keys.h"
#include "lsp/features/completion_userdata.h"
#include "lsp/features/document_tree.h"

namespace smachac::lsp {
namespace {

/// Adds candidates, each label once.
class CandidateList {
 public:
  void add(Candidate candidate) {
    bool known = std::any_of(candidates_.begin(), candidates_.end(),
                             [&](const Candidate& c) { return c.label == candidate.label; });
    if (!known && !candidate.label.empty()) candidates_.push_back(std::move(candidate));
  }
  void addOutcome(const std::string& name, std::string detail, std::string doc = "") {
    add({name, ItemKind::EnumMember, std::move(detail), std::move(doc)});
  }
  std::vector<Candidate> take() { return std::move(candidates_); }

 private:
  std::vector<Candidate> candidates_;
};

std::string quoted(const std::string& name) { return "`" + name + "`"; }

ItemKind stateKind(const ScopeState& state) {
  if (state.body() && findKey(*state.body(), "script")) return ItemKind::Module;
  return state.isContainer() ? ItemKind::Class : ItemKind::Function;
}

std::vector<Candidate> templateCandidates(TemplateLibrary& templates, bool root) {
  CandidateList list;
  for (const std::string& name : templates.names()) {
    std::optional<TemplateInfo> info = templates.find(name);
    if (!info || !info->forScripts()) continue;
    if (!info->type.empty() && info->isBase() != root) continue;
    std::string doc = info->description != info->summary ? info->description : "";
    list.add({name, ItemKind::Class, info->summary, doc});
  }
  return list.take();
}

std::vector<Candidate> subScriptCandidates(const std::vector<SubScriptFile>& files) {
  CandidateList list;
  for (const SubScriptFile& file : files) list.add({file.name, ItemKind::File, file.path, ""});
  return list.take();
}

struct Outcomes {
  std::vector<std::string> names;
  std::string source;  ///< "outcome of X", "outcome of template T"
};

/// The outcomes a state declares, else its template's.
Outcomes outcomesOf(const ScopeState& state, CompletionSources& sources) {
  Outcomes outcomes{{}, "outcome of " + state.name()};
  for (const ScopeName& name : state.listed("outcomes")) outcomes.names.push_back(name.text);
  if (!outcomes.names.empty()) return outcomes;
  if (std::optional<TemplateInfo> info = sources.templateOf(state)) {
    outcomes = {info->outcomes, "outcome of template " + info->name};
  }
  return outcomes;
}

std::vector<Candidate> transitionOutcomes(const ScopeState& state, CompletionSources& sources) {
  CandidateList list;
  std::vector<ScopeName> given = state.mapKeys("transitions");
  Outcomes outcomes = outcomesOf(state, sources);
  for (const std::string& outcome : outcomes.names) {
    if (!contains(given, outcome)) list.addOutcome(outcome, outcomes.source);
  }
  return list.take();
}

std::vector<Candidate> transitionTargets(const ScopeState& container) {
  CandidateList list;
  for (const ScopeState& sibling : container.children()) {
    std::optional<std::string> name = sibling.templateName();
    list.add({sibling.name(), stateKind(sibling), name ? "state (" + *name + ")" : "state", ""});
  }
  for (const ScopeName& outcome : container.listed("outcomes")) {
    list.addOutcome(outcome.text, "outcome of " + container.name(),
                    "Ends " + quoted(container.name()) + " with " + quoted(outcome.text) + ".");
  }
  return list.take();
}

/// Outcomes a container needs from its states: targets that are not states, and outcomes of
/// its states that have no transition (they end the container with the same name).
void addChildOutcomes(const ScopeState& state, CompletionSources& sources, CandidateList& list) {
  std::vector<ScopeState> children = state.children();
  auto is_child = [&](const std::string& name) {
    return std::any_of(children.begin(), children.end(),
                       [&](const ScopeState& c) { return c.name() == name; });
  };
  for (const ScopeState& child : children) {
    std::vector<ScopeName> mapped = child.mapKeys("transitions");
    for (const auto& [outcome, target] : child.mapPairs("transitions")) {
      if (!is_child(target)) list.addOutcome(target, "a transition of " + child.name());
    }
    for (const std::string& outcome : outcomesOf(child, sources).names) {
      if (!contains(mapped, outcome)) {
        list.addOutcome(outcome, "an outcome of " + child.name() + " without a transition");
      }
    }
  }
}

std::vector<Candidate> outcomeCandidates(const ScopeState& state, CompletionSources& sources) {
  CandidateList list;
  addChildOutcomes(state, sources, list);
  for (const ScopeName& outcome : state.mapKeys("outcome_map")) {
    list.addOutcome(outcome.text, "in the outcome map");
  }
  for (const ScopeName& outcome : state.mapKeys("transitions")) {
    list.addOutcome(outcome.text, "has a transition");
  }
  if (std::optional<TemplateInfo> info = sources.templateOf(state)) {
    for (const std::string& outcome : info->outcomes) {
      list.addOutcome(outcome, "outcome of template " + info->name);
    }
  }
  std::vector<Candidate> candidates = list.take();
  std::vector<ScopeName> declared = state.listed("outcomes");
  std::erase_if(candidates, [&](const Candidate& c) { return contains(declared, c.label); });
  return candidates;
}

std::vector<Candidate> ownOutcomes(const ScopeState& state) {
  CandidateList list;
  for (const ScopeName& outcome : state.listed("outcomes")) {
    list.addOutcome(outcome.text, "outcome of " + state.name());
  }
  return list.take();
}

/// A scalar value of a state key (`template: |`).
std::vector<Candidate> valueCandidates(const CursorScope& scope, const std::string& key,
                                       CompletionSources& sources) {
  bool root = !scope.sub_script && scope.chain.size() == 1;
  if (key == "template") return templateCandidates(sources.templates(), root);
  if (key == "script" && !root) return subScriptCandidates(sources.subScripts());
  if (key == "default_outcome") return ownOutcomes(scope.chain.back());
  return {};
}

/// An entry of a state key's mapping or list: `transitions: {x: |}`, `outcomes: [|]`...
std::vector<Candidate> entryCandidates(const CursorScope& scope, const std::string& key,
                                       CursorRole role, CompletionSources& sources) {
  const ScopeState& state = scope.chain.back();
  bool has_container = scope.chain.size() >= 2;
  if (role == CursorRole::Key && key == "transitions") return transitionOutcomes(state, sources);
  if (role == CursorRole::Key && key == "remapping") return remapKeyCandidates(state);
  if (role == CursorRole::Value && key == "transitions" && has_container) {
    return transitionTargets(scope.chain[scope.chain.size() - 2]);
  }
  if (role == CursorRole::Value && key == "remapping") return userdataCandidates(scope.chain, "");
  if (role == CursorRole::Item && key == "outcomes") return outcomeCandidates(state, sources);
  if (role == CursorRole::Item && (key == "input_keys" || key == "output_keys")) {
    return userdataCandidates(scope.chain, key);
  }
  return {};
}

}  // namespace

CompletionSources::CompletionSources(const std::string& target,
                                     std::vector<std::string> template_dirs,
                                     std::string document_path,
                                     std::vector<std::string> script_dirs)
    : target_(target),
      template_dirs_(std::move(template_dirs)),
      document_path_(std::move(document_path)),
      script_dirs_(std::move(script_dirs)) {}

CompletionSources::~CompletionSources() = default;

TemplateLibrary& CompletionSources::templates() {
  if (!templates_) templates_ = std::make_unique<TemplateLibrary>(target_, template_dirs_);
  return *templates_;
}

std::optional<TemplateInfo> CompletionSources::templateOf(const ScopeState& state) {
  std::optional<std::string> name = state.templateName();
  return name ? templates().find(*name) : std::nullopt;
}

std::vector<SubScriptFile> CompletionSources::subScripts() const {
  return findSubScripts(document_path_, script_dirs_);
}

std::vector<Candidate> completionCandidates(const CursorScope& scope, CursorRole role,
                                            CompletionSources& sources) {
  if (scope.chain.empty() || role == CursorRole::None) return {};
  const std::vector<PathSegment>& rest = scope.rest;
  const ScopeState& state = scope.chain.back();
  bool root = !scope.sub_script && scope.chain.size() == 1;
  if (rest.empty() && role == CursorRole::Key) {
    return root ? rootKeyCandidates(state, sources.templateOf(state))
                : stateKeyCandidates(state, sources.templateOf(state));
  }
  if (rest.empty() || rest[0].isItem()) return {};
  if (rest.size() == 1 && role == CursorRole::Value) {
    return valueCandidates(scope, rest[0].key, sources);
  }
  bool entry =
      rest.size() == 1 || (rest.size() == 2 && rest[1].isItem() == (role == CursorRole::Item));
  return entry ? entryCandidates(scope, rest[0].key, role, sources) : std::vector<Candidate>{};
}

}  // namespace smachac::lsp
