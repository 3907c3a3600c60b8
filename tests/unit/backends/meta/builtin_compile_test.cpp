// Every built-in template compiles whole. A compile parses the bodies of a built-in template's
// macros only when they are called (backends/tmpl/parser/deferred_macro.cpp), which is sound
// because the built-in texts are known to compile: this checks it, each template parsed at
// once (as an in-memory template) with its target's filters and tests. And the tokens the
// build stored for each are the lexer's (tools/cmake/embed_gen.cpp).
#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "backends/cpp/cpp_extensions.h"
#include "backends/smach/python_extensions.h"
#include "backends/tmpl/environment.h"
#include "backends/tmpl/lexer/lexer.h"
#include "backends/tmpl/lexer/token_table.h"
#include "templates/builtin_templates.h"

namespace {

namespace templates = smachac::templates;

TEST_CASE("every built-in template compiles, its macro bodies included") {
  size_t compiled = 0;
  for (const smachac::EmbeddedFile& file : templates::builtinTemplates()) {
    CAPTURE(file.path);
    size_t slash = file.path.find('/');
    std::string set(file.path.substr(0, slash + 1));
    if (set == "dot/") continue;  // rendered with the dot target's own filter only
    // As the targets search them: the smach target's ROS templates import smach/'s Utils.
    std::vector<std::string> sets = {set};
    if (set == "smach_ros/") sets.insert(sets.begin(), "smach/");
    smachac::tmpl::Environment env({}, sets, templates::builtinTemplates());
    smachac::generator::ValueConverter converter;
    if (set == "cpp/") {
      smachac::backends::cpp::registerCppExtensions(env, converter, false);
    } else {
      smachac::backends::smach::registerPythonExtensions(env, converter, false);
    }
    // In memory, the template is parsed whole; listBlocks compiles it and what it references.
    std::string name(file.path.substr(slash + 1));
    env.addTemplate(name, std::string(file.content));
    CHECK_NOTHROW(env.listBlocks(name));
    ++compiled;
  }
  CHECK(compiled > 50);
}

TEST_CASE("every built-in template carries the tokens the lexer makes of it") {
  for (const smachac::EmbeddedFile& file : templates::builtinTemplates()) {
    CAPTURE(file.path);
    std::string source = smachac::tmpl::normalizeSource(file.content);
    std::vector<smachac::tmpl::Token> lexed = smachac::tmpl::tokenize(source);
    std::optional<std::span<const smachac::tmpl::Token>> stored =
        smachac::tmpl::storedTokens(file.tokens, source);
    REQUIRE(stored);
    REQUIRE(stored->size() == lexed.size());
    for (size_t i = 0; i < lexed.size(); ++i) {
      CHECK(((*stored)[i].kind == lexed[i].kind && (*stored)[i].length == lexed[i].length &&
             (*stored)[i].pos == lexed[i].pos));
    }
  }
}

}  // namespace
