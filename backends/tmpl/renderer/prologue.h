// Render prologues: what a top-level render does before and around its blocks, recorded once
// per (template, skip policy) and replayed. SMACHA renders each block of a state template with
// every other block skipped, so the roots of the template and of its parents run nothing but
// texts, `from ... import` of default modules, includes, `extends` and the call site of the
// kept block. Such a run has no effect but the output, the imported names and the block table
// of the context, so the replay writes the same texts, binds the same values and calls the
// same blocks, without root frames, slot initialisation or statement dispatch (an include of a
// template with more than a text runs as execInclude runs it, with the names imported before
// it as the locals it passes).
// Rules: a root with any other statement (or a name that is not a constant, an import with
// context, a scoped block...) is not recorded and renders as before; steps, depth and error
// locations are those of the run it replaces (the recording runs in the first render and
// charges it the modules it makes, as that render's imports would have). The imports between
// two block calls are bound as one table shared by every render's context: nothing else in a
// recorded root reads the context, so they may move up to the next block call or include.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "backends/tmpl/renderer/runtime.h"

namespace smachac::tmpl {

enum class PrologueStep : uint8_t {
  EnterRoot,    // `tmpl`'s root starts (its call guard), after the extends `stmt` of `owner`
  Text,         // `text` written: `body`, texts of `owner`'s root that follow one another
  IncludeText,  // the include `stmt` of a root that is `body` (one text of `tmpl`)
  Include,      // the include `stmt` of `tmpl`, run in a derived context with `shared` as locals
  Imports,      // `shared` bound in the context (the imports up to the next block call)
  Blocks,       // `tmpl`'s kept blocks added to the block table (the extends `stmt`)
  BlockCall,    // the block call site `stmt` of `owner`'s root
};

struct PrologueAction {
  PrologueStep step;
  const Template* owner = nullptr;  // the template whose root holds `stmt`
  const Template* tmpl = nullptr;   // the template entered, included or extended
  const Stmt* stmt = nullptr;
  Body body;
  SharedVars shared;
  std::string text;  // Text: the texts of `body` joined
};

/// The recorded run of one template's root (and its parents' roots) under one skip policy.
struct RenderPrologue {
  std::vector<PrologueAction> actions;
  std::vector<Value> modules;  // the imported modules, kept alive with the values bound
};

/// Records the root run of `tmpl` under `ex`'s skip policy, or returns nullptr when it is not
/// made only of the statements above (or fails: the normal run then reports the error).
std::shared_ptr<const RenderPrologue> recordPrologue(Exec& ex, const Template& tmpl);

/// Replays `prologue` in `ctx` (a fresh context with `tmpl`'s blocks) at depth 0.
void replayPrologue(Exec& ex, const RenderPrologue& prologue, Context& ctx, std::string& out);

}  // namespace smachac::tmpl
