// extract: splitting a root state into a sub-script and a super-script.
#include "refactor/extract.h"

#include <fmt/core.h>

#include <array>

#include "frontend/shorthand.h"
#include "refactor/flow_text.h"
#include "refactor/map_edits.h"
#include "refactor/selection.h"
#include "refactor/text_edits.h"

namespace smachac::refactor {
namespace {

/// The keys a sub-script include passes on (generator.py's sub-script-persistent keys and
/// the params the include hands down).
constexpr std::array<std::string_view, 4> kCallerKeys = {"params", "userdata", "remapping",
                                                         "transitions"};

bool isCallerKey(std::string_view key) {
  std::string_view longhand = frontend::longhandOf(key).value_or(key);
  for (std::string_view k : kCallerKeys) {
    if (k == longhand) return true;
  }
  return false;
}

class Extractor {
 public:
  Extractor(const ScriptView& script, const RootState& state, std::string sub_name)
      : text_(script.text()), state_(state), body_(state.body()), sub_name_(std::move(sub_name)) {
    for (size_t i = 0; i < body_.asMap().size(); ++i) {
      (isCallerKey(body_.asMap()[i].key) ? caller_ : callee_).push_back(i);
    }
    script_key_ = keySpelling("script", usesShorthand(body_));
  }

  ExtractResult run() const {
    return {withLineBreaksOf(text_, subScript()), withLineBreaksOf(text_, superScript())};
  }

 private:
  std::string flowBody(const std::vector<size_t>& indices, std::string first) const {
    EditList none;
    for (size_t i : indices) {
      Span entry = entrySpan(text_, body_, body_.asMap()[i]);
      first += (first.empty() ? "" : ", ") + none.render(text_.text(), entry);
    }
    return "{" + first + "}";
  }

  std::string superScript() const {
    EditList edits;
    if (isFlowCollection(text_, body_)) {
      Span span = nodeSpan(text_, body_, {});
      edits.replace(span, flowBody(caller_, script_key_ + ": " + flowScalar(sub_name_)));
    } else {
      MapEditor(text_, edits).deleteEntries(body_, callee_);
      MapEditor(text_, edits).insertBefore(body_, 0, script_key_, flowScalar(sub_name_));
    }
    return edits.render(text_.text(), {0, text_.size()});
  }

  std::string subScript() const {
    EditList edits;
    bool flow_body = isFlowCollection(text_, body_);
    if (flow_body) {
      edits.replace(nodeSpan(text_, body_, {}), flowBody(callee_, ""));
    } else {
      MapEditor(text_, edits).deleteEntries(body_, caller_);
    }
    const ir::Value& list = *state_.list;
    Span item = listItemSpan(text_, list, *state_.item);
    if (isFlowCollection(text_, list)) return "- " + edits.render(text_.text(), item) + "\n";
    size_t first = text_.lineOf(item.begin);
    Span lines{text_.lineStart(first), text_.nextLineStart(lastLineOf(text_, item))};
    std::string out = dedentLines(edits.render(text_.text(), lines), text_.indentOf(first));
    if (out.empty() || out.back() != '\n') out += '\n';
    return out;
  }

  const SourceText& text_;
  const RootState& state_;
  const ir::Value& body_;
  std::string sub_name_;
  std::string script_key_;
  std::vector<size_t> caller_;  ///< entries that stay in the super-script
  std::vector<size_t> callee_;  ///< entries that move to the sub-script
};

}  // namespace

std::optional<ExtractResult> extract(const ScriptView& script, const std::string& state,
                                     const std::string& sub_name, DiagnosticEmitter& diags) {
  std::optional<size_t> index = findRootState(script, state, "extract", diags);
  if (!index) return std::nullopt;
  return Extractor(script, script.states()[*index], sub_name).run();
}

}  // namespace smachac::refactor
