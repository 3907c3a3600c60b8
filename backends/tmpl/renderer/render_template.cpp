// Running whole templates (root code, then the parent layout after `extends`), blocks with
// `super`, template modules for imports, and macro calls with Jinja2's argument binding.
#include "backends/tmpl/environment_impl.h"
#include "backends/tmpl/error.h"
#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/value_ops.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::tmpl {

Ref<Context> newContext(Exec& ex, const Template& tmpl, Value parent) {
  Ref<Context> ctx = ex.makeContext();
  ctx->setParent(std::move(parent));
  registerBlocks(ex, *ctx, tmpl);
  return ctx;
}

void registerBlocks(Exec& ex, Context& ctx, const Template& tmpl) {
  if (ctx.blocks().capacity() == 0) ctx.blocks().reserve(32);
  for (const BlockStmt* block : ex.policyEntry(tmpl).kept) {
    ctx.blocks().push_back({block->name, &tmpl, block});
  }
}

namespace {

// The root body without the blocks `skipped` removes, adjacent texts merged (see RootPlan).
std::unique_ptr<RootPlan> buildRootPlan(const Body& body, const std::vector<char>& skipped) {
  auto plan = std::make_unique<RootPlan>();
  Body run;  // adjacent texts not yet added
  auto flush = [&] {
    if (run.size() == 1) plan->body.push_back(run.front());
    if (run.size() > 1) {
      std::string& text = plan->texts.emplace_back();
      for (const Stmt* piece : run) text += static_cast<const TextStmt*>(piece)->text;
      TextStmt& merged = plan->merged.emplace_back(run.front()->pos, text);
      merged.pieces = &plan->pieces.emplace_back(run);
      plan->body.push_back(&merged);
    }
    run.clear();
  };
  for (Stmt* stmt : body) {
    if (stmt->kind == StmtKind::Block && skipped[static_cast<const BlockStmt*>(stmt)->index]) {
      continue;  // a skipped block does nothing where it stands
    }
    if (stmt->kind == StmtKind::Text) {
      run.push_back(stmt);
      continue;
    }
    flush();
    plan->body.push_back(stmt);
  }
  flush();
  return plan;
}

}  // namespace

const Body& rootBody(Exec& ex, const Template& tmpl) {
  SkipMask& mask = ex.policyEntry(tmpl);
  if (!mask.plan) mask.plan = buildRootPlan(tmpl.body(), mask.skipped);
  return mask.plan->body;
}

void renderRoot(Exec& ex, const Template& tmpl, Context& ctx, std::string& out) {
  CallGuard guard(ex, &tmpl);
  FrameHolder frame(ex, nullptr, &ctx, tmpl.rootFrame());
  initFrame(*frame, tmpl.rootFrame(), ex.registry);
  RootState root;
  Site site{frame.get(), &out, &root, true, tmpl.hasExtends()};
  execBody(ex, site, rootBody(ex, tmpl));
  if (!root.parent) return;
  try {
    renderRoot(ex, *root.parent, ctx, out);
  } catch (const Fault& fault) {
    throw tmpl.error(root.extends_pos, fault.message());
  }
}

namespace {

// `super` in block `index` of `ctx`: the next block of the same name, or an undefined value
// that says there is none.
Value superOf(Context& ctx, size_t index) {
  const std::string* name = ctx.blocks()[index].name;
  for (size_t i = index + 1; i < ctx.blocks().size(); ++i) {
    if (ctx.blocks()[i].name == name) return Value::object(new BlockRefObject(&ctx, i));
  }
  return Value::undefinedHint("there is no parent block called `" + *name + "`");
}

}  // namespace

void renderBlockAt(Exec& ex, Context& ctx, size_t index, std::string& out) {
  BlockEntry entry = ctx.blocks()[index];
  CallGuard guard(ex, entry.tmpl);
  const BlockStmt& block = *entry.block;
  FrameHolder frame(ex, nullptr, &ctx, block.frame);
  initFrame(*frame, block.frame, ex.registry);
  if (block.super_slot >= 0)
    frame->local(static_cast<uint16_t>(block.super_slot)) = superOf(ctx, index);
  Site site{frame.get(), &out, nullptr, false, false};
  execBody(ex, site, block.body);
}

Value makeModule(Exec& ex, const Template& tmpl, Ref<Context> ctx) {
  registerBlocks(ex, *ctx, tmpl);
  std::string body;
  renderRoot(ex, tmpl, *ctx, body);
  std::vector<std::pair<const std::string*, Value>> exports;
  for (const std::string* name : ctx->exported()) {
    for (const auto& [n, v] : ctx->vars()) {
      if (n == name) exports.emplace_back(n, v);
    }
  }
  return Value::object(new ModuleObject(&tmpl, std::move(exports), std::move(body)));
}

Value defaultModule(Exec& ex, const Template& tmpl) {
  Value module = ex.policyEntry(tmpl).module;
  if (module.isUndefined()) {
    ++ex.module_depth;  // the cached module's objects belong to the environment
    struct Leave {
      Exec& ex;
      ~Leave() { --ex.module_depth; }
    } leave{ex};
    Ref<Context> ctx = ex.adopt(new Context());
    ctx->setParent(Value::newDict());
    module = makeModule(ex, tmpl, std::move(ctx));
    ex.policyEntry(tmpl).module = module;
  }
  return module;
}

const Template& loadTemplate(Exec& ex, const Value& name) {
  if (name.isUndefined()) fail(name.undefinedMessage());
  if (name.isListOrTuple()) {
    for (const Value& candidate : name.list().items()) {
      if (candidate.isString() && ex.env.exists(candidate.s())) return ex.env.load(candidate.s());
    }
    fail("none of the templates " + repr(name) + " were found");
  }
  if (!name.isString()) {
    fail("a template name must be a string, not `" + std::string(typeName(name)) + "`");
  }
  return ex.env.load(name.s());
}

namespace {

// Binds call arguments to a macro's parameters the way Jinja2's Macro.__call__ does.
class MacroBinder {
 public:
  MacroBinder(const MacroStmt& node, const CallArgs& args) : node_(node), args_(args) {
    if (args.keyword.size() > 64) fail("too many keyword arguments");
  }

  // Keywords are matched (and unknown ones reported) before anything is bound; then the
  // parameters are bound in order, each default evaluated with the ones before it bound.
  void bind(Exec& ex, Frame& frame) {
    size_t n = node_.params.size();
    size_t given = std::min(n, args_.positional.size());
    SmallVector<const Value*, 8> by_keyword;
    for (size_t i = given; i < n; ++i) by_keyword.pushBack(takeKeyword(*node_.params[i]->name));
    bindSpecials(frame);
    Site site{&frame, nullptr, nullptr, false, false};
    size_t first_default = n - node_.defaults.size();
    for (size_t i = 0; i < n; ++i) {
      Value& slot = frame.slot(node_.params[i]->ref);
      const Value* v = i < given ? &args_.positional[i] : by_keyword[i - given];
      if (v && !v->isMissing()) {
        slot = *v;
      } else if (i >= first_default) {
        slot = eval(ex, site, node_.defaults[i - first_default]);
      } else {
        slot = Value::undefinedHint("parameter `" + *node_.params[i]->name + "` was not provided");
      }
    }
  }

 private:
  // Keyword names are interned when the call is made: most match by address.
  const Value* takeKeyword(const std::string& name) {
    for (size_t i = 0; i < args_.keyword.size(); ++i) {
      const std::string* keyword = args_.keyword[i].first;
      if ((taken_ >> i & 1) == 0 && (keyword == &name || *keyword == name)) {
        taken_ |= uint64_t{1} << i;
        return &args_.keyword[i].second;
      }
    }
    return nullptr;
  }

  std::string macroName() const { return node_.name ? *node_.name : std::string("caller"); }

  void bindSpecials(Frame& frame) {
    if (node_.caller_slot >= 0) {
      const Value* caller = takeKeyword("caller");
      frame.local(static_cast<uint16_t>(node_.caller_slot)) =
          caller ? *caller : Value::undefinedHint("no caller defined");
    }
    if (node_.kwargs_slot >= 0) {
      Value dict = Value::newDict();
      for (size_t i = 0; i < args_.keyword.size(); ++i) {
        if ((taken_ >> i & 1) == 0)
          dict.dict().setString(*args_.keyword[i].first, args_.keyword[i].second);
      }
      frame.local(static_cast<uint16_t>(node_.kwargs_slot)) = dict;
    } else {
      for (size_t i = 0; i < args_.keyword.size(); ++i) {
        if ((taken_ >> i & 1) == 0) {
          fail("macro `" + macroName() + "` takes no keyword argument `" + *args_.keyword[i].first +
               "`");
        }
      }
    }
    size_t n = node_.params.size();
    if (node_.varargs_slot >= 0) {
      std::vector<Value> extra;
      for (size_t i = n; i < args_.positional.size(); ++i) extra.push_back(args_.positional[i]);
      frame.local(static_cast<uint16_t>(node_.varargs_slot)) = Value::newTuple(std::move(extra));
    } else if (args_.positional.size() > n) {
      fail("macro `" + macroName() + "` takes not more than " + std::to_string(n) + " argument(s)");
    }
  }

  const MacroStmt& node_;
  const CallArgs& args_;
  uint64_t taken_ = 0;
};

}  // namespace

void MacroObject::callInto(Exec& ex, const CallArgs& args, std::string& out) const {
  CallGuard guard(ex, tmpl_);
  if (node_->deferred) tmpl_->completeMacro(*node_);
  FrameHolder frame(ex, closure_.get(), &closure_->context(), node_->frame);
  initFrame(*frame, node_->frame, ex.registry);
  MacroBinder(*node_, args).bind(ex, *frame);
  Site site{frame.get(), &out, nullptr, false, false};
  execBody(ex, site, node_->body);
}

Value MacroObject::call(Exec& ex, const CallArgs& args) const {
  std::string out;
  out.reserve(128);
  callInto(ex, args, out);
  return Value::string(std::move(out));
}

}  // namespace smachac::tmpl
