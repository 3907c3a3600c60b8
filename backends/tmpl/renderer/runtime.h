// Run-time structures of a render: the execution state (Exec), contexts (Jinja's Context:
// template-level variables, the render variables and the block table), frames of local
// slots, and the objects templates can hold (macros, `loop`, modules, `super`).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "backends/tmpl/ast/ast.h"
#include "backends/tmpl/filters/builtins.h"
#include "backends/tmpl/limits.h"
#include "backends/tmpl/renderer/call_args.h"
#include "backends/tmpl/template.h"
#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

class EnvironmentImpl;
struct RenderPrologue;

/// Which blocks a render removes, as SMACHA's SkipBlockExtension does.
struct SkipPolicy {
  std::vector<const std::string*> names;  // always skipped
  const std::string* only = nullptr;      // renderBlock: skip every name in `scope` but this
  const std::vector<const std::string*>* scope = nullptr;  // sorted by address

  /// The masks of this policy found so far, by template (each in its template's cache). An
  /// environment keeps renderBlock's policies, so a render finds them here without comparing
  /// the policies of a template's cache.
  mutable SmallVector<std::pair<const Template*, SkipMask*>, 8> masks;
  /// The same, by a hash of the template's address, as the last lookups left them.
  static constexpr size_t kRecentSlots = 16;
  mutable std::array<std::pair<const Template*, SkipMask*>, kRecentSlots> recent{};
  static size_t recentSlot(const Template& templ) {
    return (reinterpret_cast<uintptr_t>(&templ) >> 6) % kRecentSlots;
  }
  /// renderBlock's policies (kept by the environment) keep their template's render prologue
  /// (prologue.h), recorded on the first render; null if the template's roots have none.
  bool keeps_prologue = false;
  mutable bool prologue_recorded = false;
  mutable std::shared_ptr<const RenderPrologue> prologue;

  bool skips(const std::string* name) const;
  bool skipsBlock(const BlockStmt& block) const {
    return skips(block.name) || (!block.enclosing.empty() && skipsEnclosing(block));
  }

 private:
  bool skipsEnclosing(const BlockStmt& block) const;
};

struct BlockEntry {
  const std::string* name;
  const Template* tmpl;
  const BlockStmt* block;
};

/// Template-level variables that every render of a template binds alike (the names its roots
/// import, see prologue.h): the contexts of those renders share one table instead of copies.
struct SharedVars {
  std::vector<std::pair<const std::string*, Value>> vars;
  uint64_t names = 0;  // Context::nameBit of each name
};

/// Jinja's Context: what every frame of one template render resolves unknown names from.
/// A context derived for an include (or an import with context) sees its includer's variables
/// through `outer` instead of Jinja's copy of them.
class Context final : public Object {
 public:
  Context() { vars_.reserve(16); }

  /// What a fresh (or cleared and reused) context resolves unknown names from: a render's
  /// variables, or the includer's context plus the locals visible at the include.
  void setParent(Value parent) { parent_ = std::move(parent); }
  void setOuter(Ref<Context> outer) { outer_ = std::move(outer); }
  void addLocal(const std::string* name, const Value& value) {
    locals_.emplace_back(name, value);
    names_ |= nameBit(name);
  }

  /// Template-level variables, then the parent's, then globals; `missing` otherwise.
  Value resolve(const std::string* name, size_t hash, const Registry& registry) const;
  /// Inline: most names are new to the context (the filter below says so without a scan).
  void setVar(const std::string* name, const Value& value) {
    uint64_t bit = nameBit(name);
    if (names_ & bit) return replaceVar(name, value);
    names_ |= bit;
    vars_.emplace_back(name, value);
  }
  /// Binds the shared variables `shared` (which must outlive the context's use) in a context
  /// that has no variables yet; false (nothing bound) otherwise. Later bindings of the same
  /// names go to the context's own variables, which are looked up first.
  bool shareVars(const SharedVars& shared) {
    if (shared_ || !vars_.empty()) return false;
    shared_ = &shared;
    return true;
  }
  void exportName(const std::string* name);
  /// One bit per interned name (by address): `names_` has the bits of every name in `vars_`
  /// and `locals_`, so most lookups of a name that is not there skip both scans.
  static uint64_t nameBit(const std::string* name) {
    auto address = reinterpret_cast<uintptr_t>(name);
    return uint64_t{1} << ((address >> 4 ^ address >> 10) & 63);
  }
  void unexportName(const std::string* name) {
    if (!exported_.empty()) unexportListed(name);  // imports at the top of a root: nothing yet
  }

  /// Drops everything the context holds (breaks reference cycles through macros); keeps the
  /// capacity of its tables for reuse.
  void clear();
  /// The variables the context binds itself (not the shared ones: they are never exported).
  const std::vector<std::pair<const std::string*, Value>>& vars() const { return vars_; }
  const std::vector<const std::string*>& exported() const { return exported_; }
  std::vector<BlockEntry>& blocks() { return blocks_; }

 private:
  const Value* find(const std::string* name, size_t hash) const;
  void replaceVar(const std::string* name, const Value& value);
  void unexportListed(const std::string* name);

  uint64_t names_ = 0;
  const SharedVars* shared_ = nullptr;
  Value parent_;
  Ref<Context> outer_;
  std::vector<std::pair<const std::string*, Value>> locals_;
  std::vector<std::pair<const std::string*, Value>> vars_;
  std::vector<const std::string*> exported_;
  std::vector<BlockEntry> blocks_;
};

/// Local variable slots of one scope level; `parent` is the enclosing level. The slots are
/// stored inline (one allocation per frame).
class Frame final : public Object {
 public:
  static Ref<Frame> make(Frame* parent, Context* context, uint16_t num_slots);
  /// Constructs a frame in `memory` (room for the slots after it); see FrameHolder.
  static Frame* placeAt(void* memory, Frame* parent, Context* context, uint16_t num_slots) {
    auto* frame = new (memory) Frame(parent, context, num_slots);
    for (uint16_t i = 0; i < num_slots; ++i) new (frame->slots() + i) Value();
    return frame;
  }
  ~Frame() override {
    for (uint16_t i = 0; i < num_slots_; ++i) slots()[i].~Value();
  }
  static void operator delete(void* p) { ::operator delete(p); }

  Value& slot(SlotRef ref) {
    Frame* f = this;
    for (uint16_t i = 0; i < ref.up; ++i) f = f->parent_.get();
    return f->slots()[ref.slot];
  }
  Value& local(uint16_t index) { return slots()[index]; }
  Frame* parent() const { return parent_.get(); }
  Context& context() const { return *context_; }
  /// Unbinds every slot (breaks reference cycles through macros defined at this level).
  void clearSlots();

 private:
  Frame(Frame* parent, Context* context, uint16_t num_slots)
      : parent_(parent), context_(context), num_slots_(num_slots) {}
  friend class FrameHolder;
  Value* slots() { return reinterpret_cast<Value*>(this + 1); }

  Ref<Frame> parent_;
  Ref<Context> context_;
  uint16_t num_slots_;
};

/// The frame of one scope level, allocated on the stack when nothing can keep it alive
/// beyond the scope (no macro defined at that level or below) and it is small.
class FrameHolder {
 public:
  // Inline: every macro call, block, loop and template run makes one.
  FrameHolder(Exec& ex, Frame* parent, Context* context, const FrameLayout& layout) {
    static_assert(sizeof(storage_) >= sizeof(Frame) + kInlineSlots * sizeof(Value));
    if (layout.capturable || layout.num_slots > kInlineSlots) {
      placeOnHeap(ex, parent, context, layout);
      return;
    }
    frame_ = Frame::placeAt(storage_, parent, context, layout.num_slots);
    frame_->retain();  // owned by this holder: never deleted through a reference count
  }
  ~FrameHolder() {
    if (!heap_) frame_->~Frame();
  }
  FrameHolder(const FrameHolder&) = delete;
  FrameHolder& operator=(const FrameHolder&) = delete;
  Frame* get() const { return frame_; }
  Frame* operator->() const { return frame_; }
  Frame& operator*() const { return *frame_; }

 private:
  static constexpr size_t kInlineSlots = 12;
  void placeOnHeap(Exec& ex, Frame* parent, Context* context, const FrameLayout& layout);
  Frame* frame_;
  Ref<Frame> heap_;
  alignas(std::max_align_t) unsigned char storage_[2 * sizeof(void*) + 16 +
                                                   kInlineSlots * sizeof(Value) + 32];
};

/// The state of one top-level render call.
class Exec {
 public:
  /// `keep`: objects that macros may keep alive outlive the call (moduleVariables);
  /// otherwise the reference cycles they form are broken when the Exec ends.
  Exec(EnvironmentImpl& env, const SkipPolicy& skip, bool keep = false);
  ~Exec();
  Exec(const Exec&) = delete;
  Exec& operator=(const Exec&) = delete;

  EnvironmentImpl& env;
  const Registry& registry;
  const SkipPolicy& skip;
  const Template* tmpl = nullptr;  // the template whose code runs (for error locations)
  int depth = 0;

  /// Counts one execution step; raises Fault past the environment's limit.
  void step() {
    if (++steps_ > step_limit_) checkSteps(steps_);
  }
  /// Records a context or a capturable frame (see the constructor's `keep`).
  Context* adopt(Context* ctx);
  /// A fresh context owned by this call, reusing one the environment kept from an earlier
  /// call when it can.
  Context* makeContext();
  void adopt(Frame* frame);
  /// While positive, adopted objects belong to the environment's module cache.
  int module_depth = 0;
  /// Raises Fault when the native stack is close to exhaustion.
  void checkStack() const {
    auto here = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
    size_t used = stack_base_ > here ? stack_base_ - here : here - stack_base_;
    if (used > kStackBudget) failStack();
  }
  /// Which blocks of `templ` this call's skip policy removes, by BlockStmt::index.
  const std::vector<char>& skipMask(const Template& templ) { return policyEntry(templ).skipped; }
  /// The per-(template, skip policy) cache entry (skipped blocks, default module).
  SkipMask& policyEntry(const Template& templ) {
    const auto& [recent, mask] = skip.recent[SkipPolicy::recentSlot(templ)];
    return recent == &templ ? *mask : findPolicyEntry(templ);
  }

 private:
  static constexpr size_t kStackBudget = size_t{3} << 20;
  [[noreturn]] static void failStack();
  SkipMask& findPolicyEntry(const Template& templ);
  SkipMask& addPolicyEntry(const Template& templ);
  size_t cachedPolicyIndex(const Template& templ,
                           const std::vector<std::unique_ptr<SkipMask>>& cache) const;
  SmallVector<std::pair<const Template*, SkipMask*>, 2> own_found_;  // masks of own_masks_
  std::vector<std::unique_ptr<SkipMask>> own_masks_;
  static constexpr size_t kMaxCachedPolicies = 256;

  uint64_t steps_ = 0;
  uint64_t step_limit_;  // the steps of the limits below (read once: they hold for the call)
  ScopedLimits limits_;  // this environment's limits and steps_, active while rendering
  uintptr_t stack_base_;
  bool keep_;
  SmallVector<Ref<Context>, 6> contexts_;
  SmallVector<Ref<Frame>, 4> frames_;
};

/// Enters a template, macro or block: bounds the depth and switches the error location.
class CallGuard {
 public:
  // Inline: every macro call, block, include and loop-free template run passes here.
  CallGuard(Exec& ex, const Template* tmpl) : ex_(ex), saved_(ex.tmpl) {
    if (ex.depth >= kMaxDepth) failDepth();
    ex.checkStack();
    ++ex.depth;
    ex.step();
    ex.tmpl = tmpl;
  }
  ~CallGuard() {
    --ex_.depth;
    ex_.tmpl = saved_;
  }
  CallGuard(const CallGuard&) = delete;
  CallGuard& operator=(const CallGuard&) = delete;

 private:
  static constexpr int kMaxDepth = 200;
  [[noreturn]] static void failDepth();
  Exec& ex_;
  const Template* saved_;
};

struct RootState {
  const Template* parent = nullptr;  // set by `extends`
  uint32_t extends_pos = 0;          // where, for errors while entering the parent
};

/// Where statements run: the frame, the output buffer and the top-level flags.
struct Site {
  Frame* frame;
  std::string* out;
  RootState* root = nullptr;  // template root code (also inside its loops)
  bool toplevel = false;      // assignments export to the context
  bool output_check = false;  // output stops once `extends` ran

  bool suppressed() const { return output_check && root && root->parent; }
  Site inner(Frame* f) const { return Site{f, out, root, false, output_check}; }
};

// --- objects --------------------------------------------------------------------------------

class MacroObject final : public Object {
 public:
  MacroObject(const Template* tmpl, const MacroStmt* node, Ref<Frame> closure)
      : tmpl_(tmpl), node_(node), closure_(std::move(closure)) {}
  std::string_view typeName() const override { return "Macro"; }
  void repr(std::string& out) const override;
  bool isCallable() const override { return true; }
  Value call(Exec& ex, const CallArgs& args) const override;
  /// Renders the macro's output straight into `out` (what `{{ m() }}` prints).
  void callInto(Exec& ex, const CallArgs& args, std::string& out) const;

 private:
  const Template* tmpl_;
  const MacroStmt* node_;
  Ref<Frame> closure_;
};

/// `super`: renders the next block of the same name in the context's block table.
class BlockRefObject final : public Object {
 public:
  BlockRefObject(Ref<Context> ctx, size_t index) : ctx_(std::move(ctx)), index_(index) {}
  std::string_view typeName() const override { return "BlockReference"; }
  bool getAttr(std::string_view name, Value& out) const override;
  bool isCallable() const override { return true; }
  Value call(Exec& ex, const CallArgs& args) const override;

 private:
  Ref<Context> ctx_;
  size_t index_;
};

class ModuleObject final : public Object {
 public:
  ModuleObject(const Template* tmpl, std::vector<std::pair<const std::string*, Value>> exports,
               std::string body)
      : tmpl_(tmpl), exports_(std::move(exports)), body_(std::move(body)) {}
  std::string_view typeName() const override { return "TemplateModule"; }
  void repr(std::string& out) const override;
  void str(std::string& out) const override { out += body_; }
  bool getAttr(std::string_view name, Value& out) const override;
  /// The export `name` (interned) or nullptr; `hint` is where to look first, and is set to
  /// where the name was found.
  const Value* findExport(const std::string* name, size_t& hint) const {
    if (hint < exports_.size() && exports_[hint].first == name) return &exports_[hint].second;
    return scanExports(name, hint);
  }
  const std::string& body() const { return body_; }
  const Template* tmpl() const { return tmpl_; }
  const std::vector<std::pair<const std::string*, Value>>& exports() const { return exports_; }

 private:
  const Value* scanExports(const std::string* name, size_t& hint) const;

  const Template* tmpl_;
  std::vector<std::pair<const std::string*, Value>> exports_;
  std::string body_;
};

/// A method bound to a value (`items.append` not called immediately).
class MethodObject final : public Object {
 public:
  MethodObject(Value self, std::string name) : self_(std::move(self)), name_(std::move(name)) {}
  std::string_view typeName() const override { return "builtin_function_or_method"; }
  void repr(std::string& out) const override;
  bool isCallable() const override { return true; }
  Value call(Exec& ex, const CallArgs& args) const override;

 private:
  Value self_;
  std::string name_;
};

/// A global function (`range`, `dict`, ...).
class FunctionObject final : public Object {
 public:
  using Fn = Value (*)(Exec& ex, const CallArgs& args);
  FunctionObject(std::string name, Fn fn) : name_(std::move(name)), fn_(fn) {}
  std::string_view typeName() const override { return "function"; }
  void repr(std::string& out) const override;
  bool isCallable() const override { return true; }
  Value call(Exec& ex, const CallArgs& args) const override { return fn_(ex, args); }

 private:
  std::string name_;
  Fn fn_;
};

}  // namespace smachac::tmpl
