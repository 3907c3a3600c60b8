// Environment: template loading and caching, and the SMACHA operations built on the renderer
// (render, renderBlock, listBlocks, moduleVariables, metaBlock).
#include "backends/tmpl/environment.h"

#include <algorithm>
#include <atomic>
#include <functional>
#include <new>
#include <set>

#include "backends/tmpl/environment_impl.h"
#include "backends/tmpl/renderer/prologue.h"
#include "backends/tmpl/renderer/render.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {

EnvironmentImpl::EnvironmentImpl(std::vector<std::string> dirs,
                                 std::vector<std::string> builtin_sets,
                                 std::span<const EmbeddedFile> builtins)
    : loader_(std::move(dirs), std::move(builtin_sets), builtins) {}

EnvironmentImpl::~EnvironmentImpl() {
  clearModules();
  for (const Ref<Context>& ctx : kept_contexts_) ctx->clear();
  for (const Ref<Frame>& frame : kept_frames_) frame->clearSlots();
}

const Template& EnvironmentImpl::load(std::string_view name) {
  if (last_template_ && name == last_name_) return *last_template_;
  auto it = templates_.find(name);
  if (it != templates_.end()) {
    last_name_ = name;
    last_template_ = it->second.get();
    return *last_template_;
  }
  std::optional<TemplateSource> source = loader_.load(name);
  if (!source) {
    fail("template `" + std::string(name) + "` not found; looked in " +
         loader_.searchDescription());
  }
  auto compiled =
      std::make_unique<Template>(std::string(name), source->origin, source->text(), registry_,
                                 source->builtin, source->tokens, source->image);
  const Template& result = *compiled;
  templates_.emplace(std::string(name), std::move(compiled));
  return result;
}

const std::vector<const std::string*>& EnvironmentImpl::reachableBlocks(const Template& tmpl) {
  if (auto it = reachable_.find(&tmpl); it != reachable_.end()) return it->second;
  std::set<std::string> names;
  std::set<const Template*> seen;
  std::function<void(const Template&)> visit = [&](const Template& t) {
    if (!seen.insert(&t).second) return;
    for (const BlockStmt* b : t.blocks()) names.insert(*b->name);
    for (const auto& [ref, pos] : t.references()) {
      const Template* referenced = nullptr;
      try {
        referenced = &load(ref);
      } catch (const Fault& fault) {
        throw t.error(pos, fault.message());
      }
      visit(*referenced);
    }
  };
  visit(tmpl);
  std::vector<const std::string*> out;
  for (const std::string& n : names) out.push_back(intern(n));
  return reachable_.emplace(&tmpl, std::move(out)).first->second;
}

const std::vector<const std::string*>& EnvironmentImpl::reachableByAddress(const Template& tmpl) {
  if (auto it = reachable_by_address_.find(&tmpl); it != reachable_by_address_.end())
    return it->second;
  std::vector<const std::string*> names = reachableBlocks(tmpl);
  std::sort(names.begin(), names.end());
  return reachable_by_address_.emplace(&tmpl, std::move(names)).first->second;
}

const SkipPolicy& EnvironmentImpl::blockPolicy(const Template& tmpl, const std::string* only) {
  std::unique_ptr<SkipPolicy>& policy = block_policies_[{&tmpl, only}];
  if (!policy) {
    policy = std::make_unique<SkipPolicy>();
    policy->only = only;
    policy->scope = &reachableByAddress(tmpl);
    policy->keeps_prologue = true;
  }
  return *policy;
}

namespace {

// Where blockRender's cache looks first: a cheap mix of the sizes and three bytes of the block
// name (a collision costs a probe, or a slow lookup past the last probe).
size_t blockRenderHome(std::string_view name, std::string_view block) {
  if (block.empty()) return name.size();
  auto byte = [&](size_t i) { return static_cast<size_t>(static_cast<unsigned char>(block[i])); };
  return block.size() * 31 + byte(0) * 7 + byte(block.size() / 2) * 13 + byte(block.size() - 1) +
         name.size();
}

}  // namespace

std::pair<const Template*, const SkipPolicy*> EnvironmentImpl::blockRender(std::string_view name,
                                                                           std::string_view block) {
  if (block_renders_.empty()) block_renders_.resize(kBlockRenderSlots);
  size_t home = blockRenderHome(name, block);
  for (size_t probe = 0; probe < kBlockRenderProbes; ++probe) {
    const BlockRender& cached = block_renders_[(home + probe) % kBlockRenderSlots];
    if (!cached.tmpl) break;
    if (sameText(cached.block, block) && sameText(cached.name, name)) {
      return {cached.tmpl, cached.policy};
    }
  }
  const std::string* only = intern(block);
  const Template& tmpl = load(name);
  const SkipPolicy& policy = blockPolicy(tmpl, only);
  size_t probe = 0;  // the first empty slot of the probes, else the last one
  while (probe + 1 < kBlockRenderProbes && block_renders_[(home + probe) % kBlockRenderSlots].tmpl)
    ++probe;
  block_renders_[(home + probe) % kBlockRenderSlots] = {std::string(name), std::string(block),
                                                        &tmpl, &policy};
  return {&tmpl, &policy};
}

std::string* EnvironmentImpl::takeScratch() {
  if (scratch_taken_) return nullptr;
  scratch_taken_ = true;
  scratch_.clear();
  return &scratch_;
}

void EnvironmentImpl::returnScratch() {
  scratch_taken_ = false;
  if (scratch_.capacity() > kMaxScratchCapacity) std::string().swap(scratch_);
}

Ref<Context> EnvironmentImpl::takeSpareContext() {
  if (spare_contexts_.empty()) return Ref<Context>(new Context());
  Ref<Context> ctx = std::move(spare_contexts_.back());
  spare_contexts_.pop_back();
  return ctx;
}

void EnvironmentImpl::addSpareContext(Ref<Context> ctx) {
  if (spare_contexts_.size() < kMaxSpareContexts) spare_contexts_.push_back(std::move(ctx));
}

void EnvironmentImpl::clearModules() {
  for (const auto& [name, tmpl] : templates_) {
    for (const auto& mask : tmpl->skipMasks()) mask->module = Value();
  }
  for (const auto& [key, policy] : block_policies_) {  // prologues hold the modules' values
    policy->prologue = nullptr;
    policy->prologue_recorded = false;
  }
}

namespace {

SkipPolicy explicitSkips(const RenderOptions& options) {
  SkipPolicy policy;
  for (const std::string& name : options.skip_blocks) policy.names.push_back(intern(name));
  return policy;
}

Value contextDict(const Value& context) {
  if (context.isDict()) return context;
  if (context.isUndefined() || context.isNone()) return Value::newDict();
  fail("the render context must be a dict, not `" + std::string(kindName(context.kind())) + "`");
}

// Runs `body`, turning location-less faults into errors about template `name`.
template <class F>
auto guarded(std::string_view name, F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const Fault& fault) {
    throw TemplateError(std::string(name), 0, 0, fault.message());
  } catch (const std::bad_alloc&) {
    throw TemplateError(std::string(name), 0, 0, "out of memory");
  }
}

// Renders `tmpl` under `policy`, appending to `out`.
void renderInto(EnvironmentImpl& env, const Template& tmpl, const Value& context,
                const SkipPolicy& policy, std::string& out) {
  Exec ex(env, policy);
  Ref<Context> ctx = newContext(ex, tmpl, contextDict(context));
  if (policy.keeps_prologue && !policy.prologue_recorded) {
    policy.prologue = recordPrologue(ex, tmpl);
    policy.prologue_recorded = true;
  }
  if (std::shared_ptr<const RenderPrologue> prologue = policy.prologue) {
    replayPrologue(ex, *prologue, *ctx, out);  // held: the context uses its shared variables
  } else {
    renderRoot(ex, tmpl, *ctx, out);
  }
}

std::string renderWith(EnvironmentImpl& env, const Template& tmpl, const Value& context,
                       const SkipPolicy& policy) {
  std::string out;
  out.reserve(256);
  renderInto(env, tmpl, context, policy, out);
  return out;
}

// The environment's scratch text for one render, or a text of its own when a render that
// runs already holds it.
class ScratchText {
 public:
  explicit ScratchText(EnvironmentImpl& env) : env_(env), text_(env.takeScratch()) {
    if (!text_) text_ = &own_;
  }
  ~ScratchText() {
    if (text_ != &own_) env_.returnScratch();
  }
  ScratchText(const ScratchText&) = delete;
  ScratchText& operator=(const ScratchText&) = delete;
  std::string& text() { return *text_; }

 private:
  EnvironmentImpl& env_;
  std::string own_;
  std::string* text_;
};

// renderBlock's result: the render stripped, with "\n" appended unless empty. The render goes
// to the scratch text, so that it allocates only its result, and nothing when it is empty.
std::string renderStripped(EnvironmentImpl& env, const Template& tmpl, const Value& context,
                           const SkipPolicy& policy) {
  ScratchText scratch(env);
  renderInto(env, tmpl, context, policy, scratch.text());
  std::string_view stripped = unicode::strip(scratch.text());
  if (stripped.empty()) return std::string();
  std::string result;
  result.reserve(stripped.size() + 1);
  result.append(stripped).push_back('\n');
  return result;
}

}  // namespace

Environment::Environment(std::vector<std::string> template_dirs,
                         std::vector<std::string> builtin_sets,
                         std::span<const EmbeddedFile> builtins)
    : impl_(std::make_unique<EnvironmentImpl>(std::move(template_dirs), std::move(builtin_sets),
                                              builtins)) {}

namespace {

/// Set once by a process that exits right after its work (Environment::leaveToProcessExit).
std::atomic<bool> g_leave_to_process_exit{false};

}  // namespace

Environment::~Environment() {
  // Handed to the process exit: its templates, modules and values are never freed one by one
  // (about 90 K instructions of a cold compile).
  if (g_leave_to_process_exit.load(std::memory_order_relaxed)) (void)impl_.release();
}

void Environment::leaveToProcessExit() {
  g_leave_to_process_exit.store(true, std::memory_order_relaxed);
}

std::string Environment::render(std::string_view name, const Value& context,
                                const RenderOptions& options) {
  return guarded(name, [&] {
    SkipPolicy policy = explicitSkips(options);
    return renderWith(*impl_, impl_->load(name), context, policy);
  });
}

std::string Environment::renderBlock(std::string_view name, std::string_view block,
                                     const Value& context, const RenderOptions& options) {
  return guarded(name, [&] {
    if (options.skip_blocks.empty()) {
      auto [tmpl, policy] = impl_->blockRender(name, block);
      return renderStripped(*impl_, *tmpl, context, *policy);
    }
    const Template& tmpl = impl_->load(name);
    SkipPolicy policy = explicitSkips(options);
    policy.only = intern(block);
    policy.scope = &impl_->reachableByAddress(tmpl);
    return renderStripped(*impl_, tmpl, context, policy);
  });
}

std::vector<std::string> Environment::listBlocks(std::string_view name) {
  return guarded(name, [&] {
    std::vector<std::string> out;
    for (const std::string* n : impl_->reachableBlocks(impl_->load(name))) out.push_back(*n);
    return out;
  });
}

std::vector<std::pair<std::string, Value>> Environment::moduleVariables(
    std::string_view name, const Value& context, const RenderOptions& options) {
  return guarded(name, [&] {
    SkipPolicy policy = explicitSkips(options);
    Exec ex(*impl_, policy, /*keep=*/true);
    const Template& tmpl = impl_->load(name);
    Ref<Context> ctx = newContext(ex, tmpl, contextDict(context));
    std::string out;
    renderRoot(ex, tmpl, *ctx, out);
    std::vector<std::pair<std::string, Value>> vars;
    for (const std::string* exported : ctx->exported()) {
      for (const auto& [n, v] : ctx->vars()) {
        if (n == exported) vars.emplace_back(*n, v);
      }
    }
    std::sort(vars.begin(), vars.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return vars;
  });
}

std::optional<std::string> Environment::metaBlock(std::string_view name) {
  return guarded(name, [&]() -> std::optional<std::string> {
    const Template& tmpl = impl_->load(name);
    if (!tmpl.block("meta")) return std::nullopt;
    SkipPolicy policy;
    Exec ex(*impl_, policy);
    Ref<Context> ctx = newContext(ex, tmpl, Value::newDict());
    for (size_t i = 0; i < ctx->blocks().size(); ++i) {
      if (*ctx->blocks()[i].name != "meta") continue;
      std::string out;
      renderBlockAt(ex, *ctx, i, out);
      return out;
    }
    return std::nullopt;
  });
}

std::optional<std::string> Environment::resolveScriptTemplate(std::string_view name) const {
  return impl_->loader().resolveScriptName(name);
}

bool Environment::hasTemplate(std::string_view name) const { return impl_->exists(name); }

const Template& Environment::compiled(std::string_view name) { return impl_->load(name); }

void Environment::addTemplate(std::string name, std::string source) {
  impl_->loader().addMemory(std::move(name), std::move(source));
}

void Environment::setLimits(const Limits& limits) { impl_->setLimits(limits); }

void Environment::addFilter(std::string name, CustomFilter fn) {
  impl_->registry().addFilter(std::move(name), std::move(fn));
}

void Environment::addTest(std::string name, CustomTest fn) {
  impl_->registry().addTest(std::move(name), std::move(fn));
}

void Environment::addGlobal(std::string name, Value value) {
  impl_->registry().addGlobal(std::move(name), std::move(value));
  impl_->clearModules();
}

}  // namespace smachac::tmpl
