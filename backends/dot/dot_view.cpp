// Builds the dot view model from the IR.
#include "backends/dot/dot_view.h"

#include <algorithm>
#include <set>
#include <string>
#include <tuple>

namespace smachac::backends::dot {
namespace {

using tmpl::Value;

std::string nodeId(ir::StateId id) { return "n" + std::to_string(id.index); }
std::string clusterId(ir::StateId id) { return "cluster_" + std::to_string(id.index); }
std::string outcomeId(ir::StateId id, size_t k) {
  return "o" + std::to_string(id.index) + "_" + std::to_string(k);
}

/// A state starts at its name (and, for included states, again at its body in the sub-script);
/// a diagnostic belongs to the state that starts last at or before its location.
std::set<uint32_t> flaggedStates(const ir::Module& m, std::span<const Diagnostic> diagnostics) {
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>> starts;
  for (ir::StateId id : m.preorder()) {
    for (const SourceLoc& l : {m.state(id).name.loc, m.state(id).loc}) {
      starts.emplace_back(l.file, l.line, l.column, id.index);
    }
  }
  std::sort(starts.begin(), starts.end());
  std::set<uint32_t> flagged;
  for (const Diagnostic& d : diagnostics) {
    auto key = std::make_tuple(d.loc.file, d.loc.line, d.loc.column, UINT32_MAX);
    auto it = std::upper_bound(starts.begin(), starts.end(), key);
    if (it == starts.begin() || std::get<0>(*(it - 1)) != d.loc.file) continue;
    uint32_t state = std::get<3>(*(it - 1));
    if (state != m.root().index) flagged.insert(state);
  }
  return flagged;
}

class Builder {
 public:
  Builder(const ir::Module& m, std::set<uint32_t> flagged) : m_(m), flagged_(std::move(flagged)) {}

  Value container(ir::StateId id) {
    const ir::State& s = m_.state(id);
    Value v = common(id);
    v.dict().setString("cluster", Value::string(clusterId(id)));
    Value children = Value::newList();
    for (ir::StateId child : s.children) {
      children.list().items().push_back(ir::isContainer(m_.state(child).kind) ? container(child)
                                                                              : common(child));
    }
    v.dict().setString("children", children);
    v.dict().setString("outcomes", outcomes(id));
    v.dict().setString("edges", edges(id));
    if (s.children.empty()) v.dict().setString("placeholder", Value::string(entry(id)));
    return v;
  }

 private:
  Value common(ir::StateId id) {
    const ir::State& s = m_.state(id);
    Value v = Value::newDict();
    v.dict().setString("id", Value::string(nodeId(id)));
    v.dict().setString("name", Value::string(s.name.text));
    v.dict().setString(
        "template", Value::string(s.template_name ? s.template_name->text.str() : std::string()));
    v.dict().setString("kind", Value::string(std::string(ir::stateKindName(s.kind))));
    v.dict().setString("flagged", Value::boolean(flagged_.contains(id.index)));
    v.dict().setString("entry", Value::string(entry(id)));
    return v;
  }

  /// The node an edge into `id` points at: the state itself, or its container's first leaf.
  std::string entry(ir::StateId id) const {
    const ir::State& s = m_.state(id);
    if (!ir::isContainer(s.kind)) return nodeId(id);
    if (s.children.empty()) return "e" + std::to_string(id.index);
    return entry(s.children.front());
  }

  Value outcomes(ir::StateId id) const {
    const ir::State& s = m_.state(id);
    Value list = Value::newList();
    for (size_t k = 0; k < s.outcomes.size(); ++k) {
      Value o = Value::newDict();
      o.dict().setString("id", Value::string(outcomeId(id, k)));
      o.dict().setString("name", Value::string(s.outcomes[k].text));
      bool is_default = s.default_outcome && s.default_outcome->text == s.outcomes[k].text;
      o.dict().setString("default", Value::boolean(is_default));
      list.list().items().push_back(o);
    }
    return list;
  }

  /// The node an edge for `outcome` of `id` leaves from: the container's outcome node when it
  /// has one, else the state (or its entry, drawn from the cluster's border).
  std::pair<std::string, std::string> exitOf(ir::StateId id, const std::string& outcome) const {
    const ir::State& s = m_.state(id);
    if (!ir::isContainer(s.kind)) return {nodeId(id), ""};
    for (size_t k = 0; k < s.outcomes.size(); ++k) {
      if (s.outcomes[k].text == outcome) return {outcomeId(id, k), ""};
    }
    return {entry(id), clusterId(id)};
  }

  std::string parentOutcome(ir::StateId parent, const std::string& name) const {
    const std::vector<ir::Name>& outs = m_.state(parent).outcomes;
    for (size_t k = 0; k < outs.size(); ++k) {
      if (outs[k].text == name) return outcomeId(parent, k);
    }
    return "";
  }

  void addEdge(Value& list, std::pair<std::string, std::string> from, std::string to,
               std::string lhead, const std::string& label, const char* style) {
    Value e = Value::newDict();
    e.dict().setString("from", Value::string(std::move(from.first)));
    e.dict().setString("ltail", Value::string(std::move(from.second)));
    e.dict().setString("to", Value::string(std::move(to)));
    e.dict().setString("lhead", Value::string(std::move(lhead)));
    e.dict().setString("label", Value::string(label));
    e.dict().setString("style", Value::string(style));
    list.list().items().push_back(e);
  }

  void transitionEdges(Value& list, ir::StateId parent, ir::StateId child) {
    for (const ir::Transition& t : m_.state(child).transitions) {
      auto from = exitOf(child, t.outcome.text);
      if (t.target_kind == ir::TargetKind::Sibling) {
        bool nested = ir::isContainer(m_.state(t.target_state).kind);
        addEdge(list, from, entry(t.target_state), nested ? clusterId(t.target_state) : "",
                t.outcome.text, "solid");
      } else if (t.target_kind == ir::TargetKind::ContainerOutcome) {
        addEdge(list, from, parentOutcome(parent, t.target.text), "", t.outcome.text, "solid");
      }
    }
  }

  void outcomeMapEdges(Value& list, ir::StateId concurrence) {
    for (const ir::OutcomeMapEntry& e : m_.state(concurrence).outcome_map) {
      std::string to = parentOutcome(concurrence, e.outcome.text);
      for (const ir::OutcomeCondition& c : e.conditions) {
        ir::StateId child = m_.findChild(concurrence, c.child.text);
        if (!child.valid() || to.empty()) continue;
        addEdge(list, exitOf(child, c.child_outcome.text), to, "", c.child_outcome.text, "dashed");
      }
    }
  }

  Value edges(ir::StateId id) {
    Value list = Value::newList();
    if (m_.state(id).kind == ir::StateKind::Concurrence) {
      outcomeMapEdges(list, id);
      return list;
    }
    for (ir::StateId child : m_.state(id).children) transitionEdges(list, id, child);
    return list;
  }

  const ir::Module& m_;
  std::set<uint32_t> flagged_;
};

}  // namespace

tmpl::Value graphView(const ir::Module& module, std::span<const Diagnostic> diagnostics) {
  std::set<uint32_t> flagged = flaggedStates(module, diagnostics);
  size_t count = flagged.size();
  Value graph = Value::newDict();
  graph.dict().setString("name", Value::string(module.state(module.root()).name.text));
  graph.dict().setString("root", Builder(module, std::move(flagged)).container(module.root()));
  graph.dict().setString("flagged_count", Value::integer(static_cast<int64_t>(count)));
  return graph;
}

}  // namespace smachac::backends::dot
