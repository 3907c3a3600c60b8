// Warnings where the SMACH output, true to SMACHA, behaves differently from the C++ output.
#include "backends/smach/smach_lint.h"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

#include "backends/smach/python_code.h"
#include "backends/tmpl/values/value.h"
#include "ir/support/unicode.h"

namespace smachac::backends::smach {
namespace {

constexpr std::string_view kRandomOutcomeState = "RandomOutcomeState";

/// The Python code the SMACH templates write for a plain string, when they write it bare.
std::optional<std::string> bareCode(const ir::Value& value) {
  if (!value.isString() || value.forced_string) return std::nullopt;
  const std::string& text = value.asString();
  if (pythonCode(tmpl::Value::string(text)) != text) return std::nullopt;
  return text;
}

/// The first key of a map (at any depth of `value`) that sorts before the key written before
/// it, reported once per map.
void checkMapOrder(const ir::Value& value, const std::string& key, DiagnosticEmitter& diags) {
  if (value.isList()) {
    for (const ir::Value& item : value.asList()) checkMapOrder(item, key, diags);
    return;
  }
  if (!value.isMap()) return;
  const ir::Map& entries = value.asMap();
  for (size_t i = 1; i < entries.size(); ++i) {
    if (entries[i].key < entries[i - 1].key) {
      diags.emit<DiagKind::SmachMapOrder>(entries[i].key_loc, key, entries[i].key,
                                          entries[i - 1].key);
      break;
    }
  }
  for (const ir::MapEntry& entry : entries) checkMapOrder(entry.value, key, diags);
}

void checkUserdataEntry(const ir::Argument& entry, DiagnosticEmitter& diags) {
  const std::string& key = entry.key.text;
  std::string lowered = unicode::toLower(key);
  if (lowered != key) {
    diags.emit<DiagKind::SmachLowercasedUserdataKey>(entry.key.loc, key, lowered, key);
  }
  if (std::optional<std::string> code = bareCode(entry.value)) {
    diags.emit<DiagKind::SmachStringAsCode>(entry.value.loc, key, entry.value.asString(), *code);
  }
  checkMapOrder(entry.value, key, diags);
}

bool leaksCallbacks(const ir::State& state) {
  return state.kind == ir::StateKind::Leaf && state.template_name &&
         state.template_name->text == kRandomOutcomeState && state.callbacks.empty();
}

/// The leaves that receive a RandomOutcomeState's default callbacks: SMACHA exports a
/// template's top-level variables to the states rendered after it in the same container,
/// and from there into the containers among them.
class CallbackLeaks {
 public:
  CallbackLeaks(const ir::Module& module, DiagnosticEmitter& diags)
      : module_(module), diags_(diags) {}

  void check(ir::StateId container) {
    const ir::State* source = nullptr;
    std::vector<std::string> receivers;
    for (ir::StateId id : module_.state(container).children) {
      const ir::State& state = module_.state(id);
      if (source) {
        collectLeaves(id, receivers);
      } else if (leaksCallbacks(state)) {
        source = &state;
      }
      if (ir::isContainer(state.kind) && !source) check(id);
    }
    if (source && !receivers.empty()) report(*source, receivers);
  }

 private:
  void collectLeaves(ir::StateId id, std::vector<std::string>& leaves) const {
    const ir::State& state = module_.state(id);
    if (!ir::isContainer(state.kind)) {
      leaves.push_back(state.name.text);
      return;
    }
    for (ir::StateId child : state.children) collectLeaves(child, leaves);
  }

  void report(const ir::State& source, const std::vector<std::string>& receivers) {
    std::string who = fmt::format("`{}`", receivers.front());
    if (receivers.size() > 1) {
      who += fmt::format(" and {} more state{}", receivers.size() - 1,
                         receivers.size() > 2 ? "s" : "");
    }
    diags_.emit<DiagKind::SmachLeakedCallbacks>(source.name.loc, source.name.text, who);
  }

  const ir::Module& module_;
  DiagnosticEmitter& diags_;
};

}  // namespace

void checkSmachDivergences(const ir::Module& module, DiagnosticEmitter& diags) {
  for (ir::StateId id : module.preorder()) {
    for (const ir::Argument& entry : module.state(id).userdata) checkUserdataEntry(entry, diags);
  }
  CallbackLeaks(module, diags).check(module.root());
}

}  // namespace smachac::backends::smach
