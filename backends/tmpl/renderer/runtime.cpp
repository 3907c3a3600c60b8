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
    if (c->shared_ && (c->shared_->names & bit)) {
      for (const auto& [n, v] : c->shared_->vars) {
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
  if (const Value* g = registry.global(*name, hash)) return *g;
  return Value::missing(name);
}

void Context::clear() {
  names_ = 0;
  shared_ = nullptr;
  parent_ = Value();
  outer_ = nullptr;
  locals_.clear();
  vars_.clear();
  exported_.clear();
  blocks_.clear();
}

// setVar of a name whose bit is set: bound already, or another name with the same bit.
void Context::replaceVar(const std::string* name, const Value& value) {
  for (auto& [n, v] : vars_) {
    if (n == name) {
      v = value;
      return;
    }
  }
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

Ref<Frame> Frame::make(Frame* parent, Context* context, uint16_t num_slots) {
  return Ref<Frame>(placeAt(::operator new(sizeof(Frame) + num_slots * sizeof(Value)), parent,
                            context, num_slots));
}

void Frame::clearSlots() {
  for (uint16_t i = 0; i < num_slots_; ++i) slots()[i] = Value();
}

void FrameHolder::placeOnHeap(Exec& ex, Frame* parent, Context* context,
                              const FrameLayout& layout) {
  heap_ = Frame::make(parent, context, layout.num_slots);
  frame_ = heap_.get();
  if (layout.capturable) ex.adopt(frame_);
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
  for (const auto& [t, mask] : own_found_) {
    if (t == &templ) return *mask;  // not in skip.recent: the policy may outlive this call
  }
  SkipMask* found = nullptr;
  for (const auto& [t, mask] : skip.masks) {
    if (t == &templ) found = mask;
  }
  if (!found) return addPolicyEntry(templ);
  skip.recent[SkipPolicy::recentSlot(templ)] = {&templ, found};
  return *found;
}

// The index in `cache` of the entry for this call's policy: the entry made for it or, for a
// template that names no other template, one made for a policy that skips its blocks alike
// (what such a template renders and exports depends on nothing else); cache.size() if none.
size_t Exec::cachedPolicyIndex(const Template& templ,
                               const std::vector<std::unique_ptr<SkipMask>>& cache) const {
  for (size_t i = 0; i < cache.size(); ++i) {
    const SkipMask& m = *cache[i];
    if (m.only == skip.only && m.scope == skip.scope && m.names == skip.names) return i;
  }
  if (templ.namesTemplates()) return cache.size();
  auto skips_alike = [&](const SkipMask& m) {
    for (size_t b = 0; b < templ.blocks().size(); ++b) {
      if (m.skipped[b] != static_cast<char>(skip.skipsBlock(*templ.blocks()[b]))) return false;
    }
    return true;
  };
  for (size_t i = 0; i < cache.size(); ++i) {
    if (skips_alike(*cache[i])) return i;
  }
  return cache.size();
}

// The template's cache entry for this call's policy, made if it has none; recorded in the
// policy (or in this call, for an entry the full cache left to it).
SkipMask& Exec::addPolicyEntry(const Template& templ) {
  std::vector<std::unique_ptr<SkipMask>>& cache = templ.skipMasks();
  size_t index = cachedPolicyIndex(templ, cache);
  if (index == cache.size()) {
    auto m =
        std::make_unique<SkipMask>(SkipMask{skip.only, skip.scope, skip.names, {}, {}, {}, {}});
    for (const BlockStmt* block : templ.blocks()) {
      m->skipped.push_back(skip.skipsBlock(*block));
      if (!m->skipped.back()) m->kept.push_back(block);
    }
    if (cache.size() >= kMaxCachedPolicies) {  // the template's cache is full: this call's only
      SkipMask* own = own_masks_.emplace_back(std::move(m)).get();
      own_found_.emplaceBack(&templ, own);
      return *own;
    }
    cache.push_back(std::move(m));
  }
  SkipMask* found = cache[index].get();
  skip.masks.emplaceBack(&templ, found);
  skip.recent[SkipPolicy::recentSlot(templ)] = {&templ, found};
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

void Exec::failStack() { fail("template recursion is too deep"); }

void CallGuard::failDepth() {
  fail("maximum template recursion depth (" + std::to_string(kMaxDepth) + ") exceeded");
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

const Value* ModuleObject::scanExports(const std::string* name, size_t& hint) const {
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
