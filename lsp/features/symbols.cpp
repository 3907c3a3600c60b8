// textDocument/documentSymbol: the outline of a script, as hierarchical DocumentSymbols.
//   * The script is one symbol (kind Module, named by its `name`, else by its file) holding
//     its states; a sub-script document (a list of one state) is that state alone.
//   * A state is a Class when it is a container (it has `states`, or its template is
//     StateMachine or Concurrence), a Module when it includes a sub-script (`script:`), else a
//     Function; containers hold their states, recursively.
//   * `detail` is the state's template; for a sub-script inclusion, the included state's
//     template (from the analysis, when it has the state) and `from <script>`.
//   * `range` spans the state from its name to the end of its body; `selectionRange` is the name.
// Symbols come from the document tree (document_tree.h): the parsed YAML even when lowering
// failed, else the tolerant reading of the text, so a half-typed script keeps its outline.
#include <filesystem>
#include <string>

#include "lsp/features/document_tree.h"
#include "lsp/features/features.h"

namespace smachac::lsp {
namespace {

enum SymbolKind { kModule = 2, kClass = 5, kFunction = 12 };

const ir::Value* stringValue(const ir::Value& map, std::string_view key) {
  const ir::MapEntry* entry = findKey(map, key);
  return entry && entry->value.isString() ? &entry->value : nullptr;
}

class OutlineBuilder {
 public:
  explicit OutlineBuilder(const Analysis& analysis)
      : analysis_(analysis), text_(analysis.text()), lines_(text_) {}

  Json symbols(const ir::Value& root) {
    if (root.isList()) return statesOf(root, rootState());
    if (!root.isMap()) return Json::array();
    return Json::array({scriptSymbol(root)});
  }

 private:
  Json scriptSymbol(const ir::Value& root) {
    const ir::Value* name = stringValue(root, "name");
    if (name && name->asString().empty()) name = nullptr;
    Range whole{{0, 0}, lines_.positionOf(text_.size())};
    Json symbol = {{"name", name ? name->asString() : fileStem()},
                   {"kind", kModule},
                   {"range", toJson(whole)},
                   {"selectionRange", toJson(name ? lines_.rangeOf(name->loc) : Range{})},
                   {"children", Json::array()}};
    if (const ir::Value* base = stringValue(root, "template")) symbol["detail"] = base->asString();
    if (const ir::MapEntry* states = findKey(root, "states")) {
      symbol["children"] = statesOf(states->value, rootState());
    }
    return symbol;
  }

  /// The symbols of a `states` list; `parent` is the container's state in the module.
  Json statesOf(const ir::Value& states, ir::StateId parent) {
    Json symbols = Json::array();
    if (!states.isList()) return symbols;
    for (const ir::Value& item : states.asList()) {
      if (!item.isMap()) continue;
      for (const ir::MapEntry& entry : item.asMap()) {
        if (!entry.key.empty()) symbols.push_back(stateSymbol(entry, parent));
      }
    }
    return symbols;
  }

  Json stateSymbol(const ir::MapEntry& entry, ir::StateId parent) {
    ir::StateId id = childOf(parent, entry.key);
    Range selection = lines_.rangeOf(entry.key_loc);
    size_t end = entry.value.isNull() ? lines_.offsetOf(entry.key_loc) + entry.key.size()
                                      : nodeEnd(entry.value, lines_, text_);
    Json symbol = {{"name", entry.key},
                   {"kind", kindOf(entry.value)},
                   {"range", toJson(Range{selection.start, lines_.positionOf(end)})},
                   {"selectionRange", toJson(selection)},
                   {"children", Json::array()}};
    std::string detail = detailOf(entry.value, id);
    if (!detail.empty()) symbol["detail"] = detail;
    if (const ir::MapEntry* states = findKey(entry.value, "states")) {
      symbol["children"] = statesOf(states->value, id);
    }
    return symbol;
  }

  static int kindOf(const ir::Value& body) {
    if (stringValue(body, "script")) return kModule;
    const ir::Value* name = stringValue(body, "template");
    bool container_template =
        name && (name->asString() == "StateMachine" || name->asString() == "Concurrence");
    return container_template || findKey(body, "states") ? kClass : kFunction;
  }

  std::string detailOf(const ir::Value& body, ir::StateId id) const {
    const ir::Value* written = stringValue(body, "template");
    std::string name = written ? written->asString() : includedTemplate(id);
    const ir::Value* script = stringValue(body, "script");
    if (!script) return name;
    return name.empty() ? "from " + script->asString() : name + " from " + script->asString();
  }

  std::string includedTemplate(ir::StateId id) const {
    if (!id.valid()) return "";
    const std::optional<ir::Name>& name = analysis_.module->state(id).template_name;
    return name ? name->text : "";
  }

  /// The module's root (the stand-in script of a sub-script document), or an invalid id.
  ir::StateId rootState() const {
    return analysis_.module ? analysis_.module->root() : ir::StateId();
  }

  ir::StateId childOf(ir::StateId parent, const std::string& name) const {
    return parent.valid() ? analysis_.module->findChild(parent, name) : ir::StateId();
  }

  std::string fileStem() const {
    std::string stem = std::filesystem::path(analysis_.sources.path(analysis_.file)).stem();
    return stem.empty() ? "script" : stem;
  }

  const Analysis& analysis_;
  std::string_view text_;
  LineIndex lines_;
};

}  // namespace

Json documentSymbol(Workspace& workspace, const Json& params) {
  const Analysis* analysis =
      workspace.analysis(params.at("textDocument").at("uri").get<std::string>());
  if (!analysis) return nullptr;
  DocumentTree tree(*analysis);
  return OutlineBuilder(*analysis).symbols(tree.root());
}

}  // namespace smachac::lsp
