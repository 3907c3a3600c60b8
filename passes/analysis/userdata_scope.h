// The userdata of one container as its children see it. SMACH gives every container its own
// userdata; a child reaches it through its remapping; a container copies its `input_keys` in
// from its parent when it starts (a missing parent key only logs a warning, so a default set
// inside the container survives) and its `output_keys` out when it finishes.
//
// In a container's scope, keys are interned once. The model:
//   literal definitions  the container's `userdata`, then each leaf child's `userdata` in
//                        order (SMACHA renders a leaf's userdata into its parent when the
//                        parent is built, before any state runs; the last definition of a key
//                        wins); a child container's `userdata` is in its own scope
//   initially defined    literal definitions and the container's `input_keys`
//   reads of a child     its `input_keys`, through its remapping
//   writes of a child    its `output_keys`, through its remapping
//   exit reads           the container's own `output_keys`
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "ir/module.h"
#include "passes/pass.h"

namespace smachac::passes {

/// One read or write of a key.
struct KeyUse {
  uint32_t key = 0;                      ///< interned in the scope
  const ir::Name* name = nullptr;        ///< as the state declares it
  const ir::Name* scope_name = nullptr;  ///< as the scope knows it: the remapped name or `name`
  bool optional = false;                 ///< a child container's input key with its own default
};

/// One `userdata` entry that lands in the scope.
struct LiteralDef {
  uint32_t key = 0;
  const ir::Argument* arg = nullptr;
  uint32_t child = 0;  ///< the defining child, or UserdataScope::kContainer
};

class UserdataScope {
 public:
  static constexpr uint32_t kContainer = UINT32_MAX;

  UserdataScope(const ir::Module& module, ir::StateId container);

  ir::StateId container() const { return container_; }
  uint32_t childCount() const { return static_cast<uint32_t>(read_begin_.size() - 1); }
  uint32_t keyCount() const { return static_cast<uint32_t>(names_.size()); }
  std::string_view keyName(uint32_t key) const { return names_[key]; }
  std::vector<std::string> keyNames() const;
  std::optional<uint32_t> find(std::string_view name) const;

  const std::vector<LiteralDef>& literals() const { return literals_; }
  const std::vector<KeyUse>& inputs() const { return inputs_; }
  const std::vector<KeyUse>& exitReads() const { return exit_reads_; }
  std::span<const KeyUse> reads(uint32_t child) const;
  std::span<const KeyUse> writes(uint32_t child) const;

  bool initiallyDefined(uint32_t key) const { return initial_[key] != 0; }
  bool written(uint32_t key) const { return first_writer_[key] != kNone; }
  /// The first child (in document order) that writes `key`, and its write.
  std::optional<std::pair<uint32_t, const KeyUse*>> firstWriter(uint32_t key) const;

 private:
  static constexpr uint32_t kNone = UINT32_MAX;

  uint32_t intern(std::string_view name);
  KeyUse use(const ir::State& state, const ir::Name& key);
  void addLiterals(const std::vector<ir::Argument>& userdata, uint32_t child);
  void addChild(const ir::Module& module, ir::StateId child);

  ir::StateId container_;
  std::vector<std::string_view> names_;
  std::unordered_map<std::string_view, uint32_t> index_;
  std::vector<uint8_t> initial_;
  std::vector<LiteralDef> literals_;
  std::vector<KeyUse> inputs_;
  std::vector<KeyUse> exit_reads_;
  std::vector<uint32_t> read_begin_{0};
  std::vector<KeyUse> reads_;
  std::vector<uint32_t> write_begin_{0};
  std::vector<KeyUse> writes_;
  std::vector<uint32_t> first_writer_;  ///< index into writes_, per key
};

/// The scopes of one module's containers, each built on first use. A scope points into the
/// module: the cache empties itself when asked about another module (or one whose state count
/// changed), and runPipeline clears it after a transform and at the end.
class UserdataScopeCache {
 public:
  const UserdataScope& get(const ir::Module& module, ir::StateId container);
  void clear();

 private:
  const ir::Module* module_ = nullptr;
  size_t state_count_ = 0;
  std::unordered_map<uint32_t, std::unique_ptr<UserdataScope>> scopes_;
};

/// `container`'s scope from `context`'s cache: the flow, usage and types checks share it.
const UserdataScope& userdataScope(PassContext& context, const ir::Module& module,
                                   ir::StateId container);

/// The name `key` of `state` has in its parent: the remapped name, or `key` itself.
const ir::Name& remappedName(const ir::State& state, const ir::Name& key);

}  // namespace smachac::passes
