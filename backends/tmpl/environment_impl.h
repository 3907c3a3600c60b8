// Internals of Environment shared with the renderer: the registry, the loader, and the caches
// of compiled templates, default modules and reachable block names.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/loader.h"
#include "backends/tmpl/renderer/runtime.h"
#include "backends/tmpl/template.h"

namespace smachac::tmpl {

class EnvironmentImpl {
 public:
  EnvironmentImpl(std::vector<std::string> dirs, std::vector<std::string> builtin_sets,
                  std::span<const EmbeddedFile> builtins);

  /// The compiled template `name`; raises Fault if it does not exist, TemplateError if it
  /// does not compile.
  const Template& load(std::string_view name);
  bool exists(std::string_view name) const { return loader_.exists(name); }
  /// Sorted, unique names of the blocks reachable from `tmpl` (see Environment::listBlocks).
  const std::vector<const std::string*>& reachableBlocks(const Template& tmpl);
  /// The same names sorted by address (for SkipPolicy::scope).
  const std::vector<const std::string*>& reachableByAddress(const Template& tmpl);
  /// renderBlock's skip policy for block `only` of `tmpl` (without skip_blocks), kept for the
  /// environment's life so that it keeps the masks it finds (SkipPolicy::masks).
  const SkipPolicy& blockPolicy(const Template& tmpl, const std::string* only);
  /// renderBlock's template and skip policy for block `block` of template `name`, found by the
  /// two texts in a small cache (a compile renders the same few pairs thousands of times)
  /// before the template table, the intern pool and the policy table.
  std::pair<const Template*, const SkipPolicy*> blockRender(std::string_view name,
                                                            std::string_view block);
  /// Forgets the cached default modules (after globals change).
  void clearModules();
  ~EnvironmentImpl();
  /// Objects that cached modules or returned values may still use; their reference cycles
  /// are broken when the environment is destroyed.
  void keep(Context* ctx) { kept_contexts_.emplace_back(ctx); }
  void keep(Frame* frame) { kept_frames_.emplace_back(frame); }
  /// Cleared contexts no one else references, kept for the next render (saves allocating a
  /// context and its tables for each of the thousands of small renders SMACHA makes).
  Ref<Context> takeSpareContext();
  void addSpareContext(Ref<Context> ctx);
  /// An empty text that renderBlock renders into and returns (it keeps its capacity for the
  /// next render, up to kMaxScratchCapacity); nullptr while a render holds it.
  std::string* takeScratch();
  void returnScratch();

  Registry& registry() { return registry_; }
  Loader& loader() { return loader_; }
  const Limits& limits() const { return limits_; }
  void setLimits(const Limits& limits) { limits_ = limits; }

 private:
  Limits limits_;
  Registry registry_;
  Loader loader_;
  struct NameHash {
    using is_transparent = void;  // NOLINT(readability-identifier-naming): the standard name
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::unordered_map<std::string, std::unique_ptr<Template>, NameHash, std::equal_to<>> templates_;
  // The template load() returned last (SMACHA renders one template's blocks in a row).
  std::string last_name_;
  const Template* last_template_ = nullptr;
  std::unordered_map<const Template*, std::vector<const std::string*>> reachable_;
  std::unordered_map<const Template*, std::vector<const std::string*>> reachable_by_address_;
  struct PolicyKeyHash {
    size_t operator()(const std::pair<const Template*, const std::string*>& key) const {
      return std::hash<const void*>{}(key.first) * 31 + std::hash<const void*>{}(key.second);
    }
  };
  std::unordered_map<std::pair<const Template*, const std::string*>, std::unique_ptr<SkipPolicy>,
                     PolicyKeyHash>
      block_policies_;
  struct BlockRender {
    std::string name;
    std::string block;
    const Template* tmpl = nullptr;
    const SkipPolicy* policy = nullptr;
  };
  static constexpr size_t kBlockRenderSlots = 64;  // by a mix of the names (blockRenderHome)
  static constexpr size_t kBlockRenderProbes = 4;  // linearly from there
  std::vector<BlockRender> block_renders_;         // sized on the first renderBlock
  std::vector<Ref<Context>> kept_contexts_;
  std::vector<Ref<Frame>> kept_frames_;
  static constexpr size_t kMaxSpareContexts = 8;
  std::vector<Ref<Context>> spare_contexts_;
  static constexpr size_t kMaxScratchCapacity = size_t{64} << 10;
  std::string scratch_;
  bool scratch_taken_ = false;
};

inline const Registry& registryOf(EnvironmentImpl& env) { return env.registry(); }

}  // namespace smachac::tmpl
