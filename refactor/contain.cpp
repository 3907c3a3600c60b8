// contain: the steps in order, and the container's text.
#include "refactor/contain.h"

#include <fmt/core.h>

#include "refactor/contain_keys.h"
#include "refactor/contain_leaks.h"
#include "refactor/contain_outcomes.h"
#include "refactor/contain_params.h"
#include "refactor/contain_userdata.h"
#include "refactor/flow_text.h"

namespace smachac::refactor {
namespace {

using Entries = std::vector<std::pair<std::string, std::string>>;  ///< longhand key, YAML text

bool checkName(const ScriptView& script, const ContainRequest& request, Selection selection,
               DiagnosticEmitter& diags) {
  for (size_t i = 0; i < script.states().size(); ++i) {
    const RootState& state = script.states()[i];
    if (selection.contains(i) || state.name() != request.name) continue;
    diags.emit<DiagKind::ContainerNameTaken>(state.entry->key_loc, request.name,
                                             "a root state of the script");
    return false;
  }
  const ir::Module& module = script.module();
  for (const ir::Name& outcome : module.state(module.root()).outcomes) {
    if (outcome.text != request.name) continue;
    diags.emit<DiagKind::ContainerNameTaken>(outcome.loc, request.name, "an outcome of the script");
    return false;
  }
  return true;
}

std::vector<std::string> outcomeNames(const OutcomePlan& plan) {
  std::vector<std::string> names;
  for (const ContainerOutcome& o : plan.outcomes) names.push_back(o.name);
  return names;
}

std::string outcomeMapText(const OutcomePlan& plan) {
  Entries entries;
  for (const OutcomeMapEntry& entry : plan.outcome_map) {
    Entries conditions;
    for (const OutcomeCondition& c : entry.conditions) {
      conditions.emplace_back(c.state, flowScalar(c.outcome));
    }
    entries.emplace_back(entry.outcome, flowMap(conditions));
  }
  return flowMap(entries);
}

std::string transitionsText(const OutcomePlan& plan) {
  Entries entries;
  for (const ContainerOutcome& o : plan.outcomes) {
    if (o.target) entries.emplace_back(o.name, flowScalar(*o.target));
  }
  return entries.empty() ? std::string() : flowMap(entries);
}

/// The container's keys but `states`, in SMACHA's order; empty ones left out.
Entries containerKeys(const ContainScope& scope, const std::vector<ContainerParam>& params,
                      const KeyPlan& keys, const OutcomePlan& plan) {
  Entries out;
  out.emplace_back("template", scope.concurrence() ? "Concurrence" : "StateMachine");
  Entries param_texts;
  for (const ContainerParam& p : params) {
    param_texts.emplace_back(p.key, inlineText(scope.text(), scope.edits, *p.value, p.span));
  }
  if (!param_texts.empty()) out.emplace_back("params", flowMap(param_texts));
  if (!keys.input_keys.empty()) out.emplace_back("input_keys", flowNameList(keys.input_keys));
  if (!keys.output_keys.empty()) out.emplace_back("output_keys", flowNameList(keys.output_keys));
  Entries remapping;
  for (const auto& [key, parent] : keys.remapping) remapping.emplace_back(key, flowScalar(parent));
  if (!remapping.empty()) out.emplace_back("remapping", flowMap(remapping));
  out.emplace_back("outcomes", flowNameList(outcomeNames(plan)));
  if (plan.default_outcome) out.emplace_back("default_outcome", flowScalar(*plan.default_outcome));
  if (!plan.outcome_map.empty()) out.emplace_back("outcome_map", outcomeMapText(plan));
  std::string transitions = transitionsText(plan);
  if (!transitions.empty()) out.emplace_back("transitions", transitions);
  return out;
}

class Assembler {
 public:
  Assembler(const ContainScope& scope, Entries keys) : scope_(scope), keys_(std::move(keys)) {
    const RootState& first = scope.root(scope.selection.first);
    shorthand_ = usesShorthand(first.body());
    flow_ = isFlowCollection(scope.text(), *first.list);
  }

  std::string run() const {
    const SourceText& text = scope_.text();
    Span range = selectedRange();
    std::string out = scope_.edits.render(text.text(), {0, range.begin});
    out += flow_ ? flowContainer(range) : blockContainer(range);
    out += scope_.edits.render(text.text(), {range.end, text.size()});
    return out;
  }

 private:
  Span selectedRange() const {
    const SourceText& text = scope_.text();
    const RootState& first = scope_.root(scope_.selection.first);
    const RootState& last = scope_.root(scope_.selection.last());
    Span begin = listItemSpan(text, *first.list, *first.item);
    Span end = listItemSpan(text, *last.list, *last.item);
    if (flow_) return {begin.begin, end.end};
    size_t first_line = text.lineOf(begin.begin);
    size_t dash = text.indentOf(first_line);
    while (first_line > 0 && text.isCommentLine(first_line - 1) &&
           text.indentOf(first_line - 1) <= dash) {
      --first_line;  // the comment lines right above the first state belong to it
    }
    return {text.lineStart(first_line), text.nextLineStart(lastLineOf(text, end))};
  }

  std::string key(std::string_view longhand) const { return keySpelling(longhand, shorthand_); }

  std::string flowContainer(Span range) const {
    std::string body;
    for (const auto& [k, value] : keys_) body += key(k) + ": " + value + ", ";
    body += key("states") + ": [" + scope_.edits.render(scope_.text().text(), range) + "]";
    return flowScalar(scope_.request.name) + ": {" + body + "}";
  }

  std::string blockContainer(Span range) const {
    const SourceText& text = scope_.text();
    const RootState& first = scope_.root(scope_.selection.first);
    size_t dash = text.indentOf(text.lineOf(nodeStart(text, *first.item)));
    size_t name_column = text.columnOf(text.offsetOf(first.entry->key_loc));
    const ir::Value& body = first.body();
    size_t body_column = !isFlowCollection(text, body) && !body.asMap().empty()
                             ? text.columnOf(text.offsetOf(body.asMap().front().key_loc))
                             : name_column + 2;
    size_t states_key = text.columnOf(text.offsetOf(scope_.script.statesEntry().key_loc));
    size_t list_offset = dash > states_key ? dash - states_key : 0;
    std::string pad(body_column, ' ');
    std::string out =
        fmt::format("{}- {}:\n", std::string(dash, ' '), flowScalar(scope_.request.name));
    for (const auto& [k, value] : keys_) out += fmt::format("{}{}: {}\n", pad, key(k), value);
    out += fmt::format("{}{}:\n", pad, key("states"));
    std::string moved = scope_.edits.render(text.text(), range);
    return out + indentLines(moved, body_column - dash + list_offset);
  }

  const ContainScope& scope_;
  Entries keys_;
  bool shorthand_ = false;
  bool flow_ = false;
};

}  // namespace

std::optional<std::string> contain(const ScriptView& script, const ContainRequest& request,
                                   DiagnosticEmitter& diags) {
  std::optional<Selection> selection = selectRun(script, request.states, diags);
  if (!selection || !checkName(script, request, *selection, diags)) return std::nullopt;
  EditList edits;
  EntryDeletions deletions;
  ContainScope scope{script, request, *selection, edits, deletions, diags};
  TransitionEdits transitions;
  std::optional<OutcomePlan> outcomes = planOutcomes(scope, transitions);
  if (!outcomes) return std::nullopt;
  redirectIntoContainer(scope, transitions);
  transitions.apply(scope);
  std::vector<ContainerParam> params = liftParams(scope);
  keepLeakedParams(scope);
  UserdataPlan userdata = liftUserdata(scope);
  KeyPlan keys = inferKeys(scope, userdata);
  if (diags.hasErrors()) return std::nullopt;
  deletions.apply(scope.maps());
  std::string out = Assembler(scope, containerKeys(scope, params, keys, *outcomes)).run();
  return withLineBreaksOf(script.text(), std::move(out));
}

}  // namespace smachac::refactor
