// The IR text printer.
#include "ir/printer.h"

#include <fmt/core.h>

#include "ir/type.h"
#include "ir/value_text.h"

namespace smachac::ir {
namespace {

class Printer {
 public:
  Printer(const Module& module, const SourceManager& sources)
      : module_(module), sources_(sources) {}

  std::string run() {
    if (module_.root().valid()) printState(module_.root(), 0);
    return std::move(out_);
  }

 private:
  std::string loc(SourceLoc l) const {
    if (!l.hasFile()) return "@?";
    std::string prefix;
    if (!module_.files().empty() && l.file != module_.files().front()) {
      prefix = sources_.path(l.file) + ":";
    }
    return fmt::format("@{}{}:{}", prefix, l.line, l.column);
  }

  void line(int depth, const std::string& text) {
    out_.append(depth * 2, ' ');
    out_ += text;
    out_ += '\n';
  }

  static std::string names(const std::vector<Name>& list) {
    std::string out = "[";
    for (const Name& n : list) out += (out.size() > 1 ? ", " : "") + formatKey(n.text);
    return out + "]";
  }

  void printArguments(int depth, std::string_view field, const std::vector<Argument>& args,
                      bool typed) {
    if (args.empty()) return;
    line(depth, std::string(field) + ":");
    for (const Argument& a : args) {
      std::string type = typed ? Type::ofValue(a.value).str() + " = " : "";
      line(depth + 1, formatKey(a.key.text) + ": " + type + formatValue(a.value));
    }
  }

  void printTransitions(int depth, const State& s) {
    if (s.transitions.empty()) return;
    line(depth, "transitions:");
    for (const Transition& t : s.transitions) {
      line(depth + 1, fmt::format("{} -> {} ({})", formatKey(t.outcome.text),
                                  formatKey(t.target.text), targetKindName(t.target_kind)));
    }
  }

  void printOutcomeMap(int depth, const State& s) {
    if (s.outcome_map.empty()) return;
    line(depth, "outcome_map:");
    for (const OutcomeMapEntry& e : s.outcome_map) {
      std::string conditions;
      for (const OutcomeCondition& c : e.conditions) {
        conditions += (conditions.empty() ? "" : ", ") + formatKey(c.child.text) + ": " +
                      formatKey(c.child_outcome.text);
      }
      line(depth + 1, formatKey(e.outcome.text) + " <- {" + conditions + "}");
    }
  }

  void printFields(int depth, const State& s) {
    if (!s.outcomes.empty()) line(depth, "outcomes: " + names(s.outcomes));
    if (!s.input_keys.empty()) line(depth, "input_keys: " + names(s.input_keys));
    if (!s.output_keys.empty()) line(depth, "output_keys: " + names(s.output_keys));
    if (s.params) line(depth, "params: " + formatValue(*s.params));
    printArguments(depth, "userdata", s.userdata, true);
    if (!s.remapping.empty()) {
      line(depth, "remapping:");
      for (const Remap& r : s.remapping) {
        line(depth + 1, formatKey(r.key.text) + " <- " + formatKey(r.parent_key.text));
      }
    }
    printArguments(depth, "callbacks", s.callbacks, false);
    if (s.default_outcome) line(depth, "default_outcome: " + formatKey(s.default_outcome->text));
    printOutcomeMap(depth, s);
    printTransitions(depth, s);
    printArguments(depth, "args", s.args, true);
  }

  void printState(StateId id, int depth) {
    const State& s = module_.state(id);
    std::string header = fmt::format("{} {}", stateKindName(s.kind), formatKey(s.name.text));
    if (s.template_name) header += " template=" + formatKey(s.template_name->text);
    header += " " + loc(s.loc);
    for (const Inclusion& inc : s.included_from) {
      header += fmt::format(" (script {} {})", formatKey(inc.script.text), loc(inc.script.loc));
    }
    line(depth, header);
    printFields(depth + 1, s);
    for (StateId child : s.children) printState(child, depth + 1);
  }

  const Module& module_;
  const SourceManager& sources_;
  std::string out_;
};

}  // namespace

std::string printModule(const Module& module, const SourceManager& sources) {
  return Printer(module, sources).run();
}

}  // namespace smachac::ir
