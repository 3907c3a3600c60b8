// A loaded script as both the tools need it: the lowered module (what the script means) and
// the YAML tree with locations plus its text (how it is written). Rules:
//   * the script must lower without errors (every frontend diagnostic is reported)
//   * the root states are the items of the root `states` list in document order, nested
//     lists flattened; the i-th is the root module state's i-th child
//   * keys are found in longhand or shorthand spelling (`transitions` or `t`)
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/lower.h"
#include "ir/module.h"
#include "ir/support/diagnostic_emitter.h"
#include "ir/support/source_manager.h"
#include "refactor/source_text.h"

namespace smachac::refactor {

/// A state of the root `states` list, as written.
struct RootState {
  const ir::MapEntry* entry = nullptr;  ///< NAME: body
  const ir::Value* item = nullptr;      ///< the list item (a one-key mapping)
  const ir::Value* list = nullptr;      ///< the list holding the item
  ir::StateId id;                       ///< the lowered state

  const std::string& name() const { return entry->key; }
  const ir::Value& body() const { return entry->value; }
};

class ScriptView {
 public:
  /// Lowers `path` and reads its YAML; nullopt (with diagnostics) when it has errors.
  static std::optional<ScriptView> load(const std::string& path,
                                        const frontend::FrontendOptions& options,
                                        SourceManager& sources, DiagnosticEmitter& diags);
  /// The same for a script's text in memory (an editor's unsaved document); `path` names it
  /// in diagnostics and is where its sub-scripts are looked up from.
  static std::optional<ScriptView> loadText(const std::string& path, std::string text,
                                            const frontend::FrontendOptions& options,
                                            SourceManager& sources, DiagnosticEmitter& diags);

  ScriptView(ScriptView&&) = default;
  ScriptView& operator=(ScriptView&&) = default;
  ScriptView(const ScriptView&) = delete;  // holds pointers into its own tree
  ScriptView& operator=(const ScriptView&) = delete;

  const ir::Module& module() const { return module_; }
  const SourceText& text() const { return text_; }
  uint32_t file() const { return file_; }
  const ir::Value& root() const { return root_; }
  const ir::MapEntry& statesEntry() const { return *states_entry_; }
  const std::vector<RootState>& states() const { return states_; }
  const ir::State& state(size_t index) const { return module_.state(states_[index].id); }

  std::optional<size_t> find(std::string_view name) const;
  std::vector<std::string> names() const;

 private:
  /// The view of a module lowering just made, when there were no errors.
  static std::optional<ScriptView> fromLowered(std::optional<ir::Module> module,
                                               SourceManager& sources, DiagnosticEmitter& diags);
  ScriptView(ir::Module module, uint32_t file, std::string text, ir::Value root);
  void collect(const ir::Value& list);

  ir::Module module_;
  uint32_t file_ = 0;
  SourceText text_;
  ir::Value root_;
  const ir::MapEntry* states_entry_ = nullptr;
  std::vector<RootState> states_;
};

/// The entry of `map` for a longhand key written long or short, or nullptr; its index.
const ir::MapEntry* findKey(const ir::Value& map, std::string_view longhand);
std::optional<size_t> findKeyIndex(const ir::Value& map, std::string_view longhand);

/// Whether any key of `map` is a shorthand.
bool usesShorthand(const ir::Value& map);

/// How to spell `longhand` in a mapping written in shorthand or not.
std::string keySpelling(std::string_view longhand, bool shorthand);

}  // namespace smachac::refactor
