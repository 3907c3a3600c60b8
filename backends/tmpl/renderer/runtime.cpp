// Contexts, frames' execution state, skip policies and the printable/callable run-time objects.
#include "backends/tmpl/renderer/runtime.h"

#include <algorithm>

#include "backends/tmpl/environment_impl.h"
#include "backends/tmpl/error.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/python_text.h"

namespace smachac::tmpl {
namespace {

constexpr int kMaxDepth = 200;
constexpr size_t kStackBudget = size_t{3} << 20;

}  // namespace

bool SkipPolicy::skips(const std::string* name) const {
  if (!names.empty() && std::find(names.begin(), names.end(), name) != names.end()) return true;
  return only && name != only && std::binary_search(scope->begin(), scope->end(), name);
}

bool SkipPolicy::skipsEnclosing(const BlockStmt& block) const {
  return std::any_of(block.enclosing.begin(), block.enclosing.end(),
                     [this](const std::string* n) { return skips(n); });
}

const Value* Context::find(const std::string* name, size_t hash) const {
  uint64_t bit = nameBit(name);
  for (const Context* c = this; c; c = c->outer_.get()) {
    if (c->names_ & bit) {
      for (const auto& [n, v] : c->vars_) {
        if (n == name) return &v;
      }
      for (const auto& [n, v] : c->locals_) {
        if (n == name) return &v;
      }
    }
    if (c->parent_.isDict()) {
      if (const Value* v = c->parent_.dict().findString(*name, hash)) return v;
    }
  }
  return nullptr;
}

Value Context::resolve(const std::string* name, size_t hash, const Registry& registry) const {
  if (const Value* v = find(name, hash)) return *v;
  if (const Value* g = registry.global(*name)) return *g;
  return Value::missing(name);
}

void Context::clear() {
  names_ = 0;
  parent_ = Value();
  outer_ = nullptr;
  locals_.clear();
  vars_.clear();
  exported_.clear();
  blocks_.clear();
}

void Context::setVar(const std::string* name, const Value& value) {
  uint64_t bit = nameBit(name);
  if (names_ & bit) {
    for (auto& [n, v] : vars_) {
      if (n == name) {
        v = value;
        return;
      }
    }
  }
  names_ |= bit;
  vars_.emplace_back(name, value);
}

void Context::exportName(const std::string* name) {
  if (std::find(exported_.begin(), exported_.end(), name) == exported_.end()) {
    exported_.push_back(name);
  }
}

void Context::unexportListed(const std::string* name) {
  exported_.erase(std::remove(exported_.begin(), exported_.end(), name), exported_.end());
}

Frame* Frame::placeAt(void* memory, Frame* parent, Context* context, uint16_t num_slots) {
  auto* frame = new (memory) Frame(parent, context, num_slots);
  for (uint16_t i = 0; i < num_slots; ++i) new (frame->slots() + i) Value();
  return frame;
}

Ref<Frame> Frame::make(Frame* parent, Context* context, uint16_t num_slots) {
  return Ref<Frame>(placeAt(::operator new(sizeof(Frame) + num_slots * sizeof(Value)), parent,
                            context, num_slots));
}

void Frame::clearSlots() {
  for (uint16_t i = 0; i < num_slots_; ++i) slots()[i] = Value();
}

FrameHolder::FrameHolder(Exec& ex, Frame* parent, Context* context, const FrameLayout& layout) {
  static_assert(sizeof(storage_) >= sizeof(Frame) + kInlineSlots * sizeof(Value));
  if (layout.capturable || layout.num_slots > kInlineSlots) {
    heap_ = Frame::make(parent, context, layout.num_slots);
    frame_ = heap_.get();
    if (layout.capturable) ex.adopt(frame_);
    return;
  }
  frame_ = Frame::placeAt(storage_, parent, context, layout.num_slots);
  frame_->retain();  // owned by this holder: never deleted through a reference count
}

FrameHolder::~FrameHolder() {
  if (!heap_) frame_->~Frame();
}

Frame::~Frame() {
  for (uint16_t i = 0; i < num_slots_; ++i) slots()[i].~Value();
}

Exec::Exec(EnvironmentImpl& environment, const SkipPolicy& skip_policy, bool keep)
    : env(environment),
      registry(registryOf(environment)),
      skip(skip_policy),
      step_limit_(environment.limits().steps),
      limits_(environment.limits(), steps_),
      keep_(keep) {
  stack_base_ = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
}

SkipMask& Exec::findPolicyEntry(const Template& templ) {
  SkipMask* found = nullptr;
  for (const auto& [t, mask] : masks_) {
    if (t == &templ) found = mask;
  }
  if (!found) {
    std::vector<std::unique_ptr<SkipMask>>& cache = templ.skipMasks();
    auto matches = [&](const SkipMask& m) {
      return m.only == skip.only && m.scope == skip.scope && m.names == skip.names;
    };
    size_t index = 0;
    while (index < cache.size() && !matches(*cache[index])) ++index;
    if (index < cache.size()) {
      found = cache[index].get();
    } else {
      auto m = std::make_unique<SkipMask>(SkipMask{skip.only, skip.scope, skip.names, {}, {}, {}});
      for (const BlockStmt* block : templ.blocks()) m->skipped.push_back(skip.skipsBlock(*block));
      found = m.get();
      if (cache.size() < kMaxCachedPolicies) {
        cache.push_back(std::move(m));
      } else {
        own_masks_.push_back(std::move(m));  // the template's cache is full: this call's only
      }
    }
    masks_.emplaceBack(&templ, found);
  }
  last_template_ = &templ;
  last_mask_ = found;
  return *found;
}

Exec::~Exec() {
  for (const Ref<Context>& ctx : contexts_) ctx->clear();
  for (const Ref<Frame>& frame : frames_) frame->clearSlots();
  for (Ref<Frame>& frame : frames_) frame = nullptr;  // frames hold their contexts
  for (Ref<Context>& ctx : contexts_) {
    if (!ctx->shared()) env.addSpareContext(std::move(ctx));
  }
}

Context* Exec::makeContext() {
  Ref<Context> ctx = env.takeSpareContext();
  return adopt(ctx.get());
}

Context* Exec::adopt(Context* ctx) {
  if (keep_ || module_depth > 0) {
    env.keep(ctx);
  } else {
    contexts_.emplaceBack(ctx);
  }
  return ctx;
}

void Exec::adopt(Frame* frame) {
  if (keep_ || module_depth > 0) {
    env.keep(frame);
  } else {
    frames_.emplaceBack(frame);
  }
}

void Exec::checkStack() const {
  auto here = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
  size_t used = stack_base_ > here ? stack_base_ - here : here - stack_base_;
  if (used > kStackBudget) fail("template recursion is too deep");
}

CallGuard::CallGuard(Exec& ex, const Template* tmpl) : ex_(ex), saved_(ex.tmpl) {
  if (ex.depth >= kMaxDepth) {
    fail("maximum template recursion depth (" + std::to_string(kMaxDepth) + ") exceeded");
  }
  ex.checkStack();
  ++ex.depth;
  ex.step();
  ex.tmpl = tmpl;
}

CallGuard::~CallGuard() {
  --ex_.depth;
  ex_.tmpl = saved_;
}

void MacroObject::repr(std::string& out) const {
  out += "<Macro ";
  if (node_->name) {
    appendPythonStringRepr(out, *node_->name);
  } else {
    out += "'caller'";
  }
  out += ">";
}

bool BlockRefObject::getAttr(std::string_view name, Value& out) const {
  if (name != "super") return false;
  auto& blocks = ctx_->blocks();
  for (size_t i = index_ + 1; i < blocks.size(); ++i) {
    if (blocks[i].name == blocks[index_].name) {
      out = Value::object(new BlockRefObject(ctx_, i));
      return true;
    }
  }
  out = Value::undefinedHint("there is no parent block called `" + *blocks[index_].name + "`");
  return true;
}

Value BlockRefObject::call(Exec& ex, const CallArgs&) const {
  std::string out;
  renderBlockAt(ex, *ctx_, index_, out);
  return Value::string(std::move(out));
}

void ModuleObject::repr(std::string& out) const {
  out += "<TemplateModule ";
  appendPythonStringRepr(out, tmpl_->name());
  out += ">";
}

bool ModuleObject::getAttr(std::string_view name, Value& out) const {
  for (const auto& [n, v] : exports_) {
    if (n->data() == name.data() || *n == name) {
      out = v;
      return true;
    }
  }
  return false;
}

const Value* ModuleObject::findExport(const std::string* name, size_t& hint) const {
  if (hint < exports_.size() && exports_[hint].first == name) return &exports_[hint].second;
  for (size_t i = 0; i < exports_.size(); ++i) {
    if (exports_[i].first == name) {
      hint = i;
      return &exports_[i].second;
    }
  }
  return nullptr;
}

void MethodObject::repr(std::string& out) const {
  out += "<built-in method " + name_ + " of " + std::string(tmpl::typeName(self_)) + " object>";
}

Value MethodObject::call(Exec& ex, const CallArgs& args) const {
  Value out;
  if (!callMethod(ex, self_, name_, args, out)) {
    fail("`" + std::string(tmpl::typeName(self_)) + "` object has no method `" + name_ + "`");
  }
  return out;
}

void FunctionObject::repr(std::string& out) const { out += "<function " + name_ + ">"; }

}  // namespace smachac::tmpl
