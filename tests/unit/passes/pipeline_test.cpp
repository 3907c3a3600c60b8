// passes/pipeline: the pass table and how the pipeline runs it.
#include <doctest/doctest.h>

#include <set>
#include <string>

#include "passes/pipeline.h"
#include "tests/unit/passes/compile.h"

namespace smachac::passes {
namespace {

constexpr const char* kUnreachable = R"(name: p
template: Base
outcomes: [done]
states:
  - A: {template: T, outcomes: [ok], transitions: {ok: done}}
  - B: {template: T, outcomes: [ok], transitions: {ok: A}}
)";

TEST_CASE("the pass table has unique kebab-case names and one function per pass") {
  std::set<std::string_view> names;
  for (const PassInfo& pass : passTable()) {
    CHECK(names.insert(pass.name).second);
    CHECK(pass.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz-") == std::string_view::npos);
    CHECK_FALSE(pass.description.empty());
    CHECK((pass.kind == PassKind::Check) == (pass.check != nullptr));
    CHECK((pass.kind == PassKind::Transform) == (pass.transform != nullptr));
    CHECK(findPass(pass.name) == &pass);
  }
  CHECK(findPass("no-such-pass") == nullptr);
}

TEST_CASE("transforms run only when optimising") {
  auto c = testing::lower(kUnreachable);
  PassContext context = c->context();
  PipelineOptions options;
  CHECK(runPipeline(*c->module, context, options));
  CHECK(c->module->state(c->module->root()).children.size() == 2);
  CHECK(c->kinds() == std::vector<std::string>{"unreachable-state"});
  options.optimize = true;
  CHECK(runPipeline(*c->module, context, options));
  CHECK(c->module->state(c->module->root()).children.size() == 1);
}

TEST_CASE("disabled passes do not run; print_ir sees the passes asked for") {
  auto c = testing::lower(kUnreachable);
  PassContext context = c->context();
  PipelineOptions options;
  options.optimize = true;
  options.disabled = {"check-reachability", "prune-unreachable-states"};
  options.print_ir_after = "all";
  std::vector<std::string> printed;
  options.print_ir = [&](std::string_view pass, const ir::Module&) { printed.emplace_back(pass); };
  CHECK(runPipeline(*c->module, context, options));
  CHECK(c->kinds().empty());
  CHECK(c->module->state(c->module->root()).children.size() == 2);
  CHECK(printed.size() == passTable().size() - 2);
}

TEST_CASE("transforms do not run on a module with errors") {
  auto c = testing::lower(R"(name: p
template: Base
outcomes: [done]
states:
  - A: {template: T, outcomes: [ok], transitions: {ok: NOPE}}
  - B: {template: T, outcomes: [ok], transitions: {ok: A}}
)");
  PassContext context = c->context();
  PipelineOptions options;
  options.optimize = true;
  CHECK_FALSE(runPipeline(*c->module, context, options));
  CHECK(c->module->state(c->module->root()).children.size() == 2);
}

}  // namespace
}  // namespace smachac::passes
