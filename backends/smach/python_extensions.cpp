// Python string escaping and the forced-string test for the SMACH templates.
#include "backends/smach/python_extensions.h"

#include "backends/tmpl/value_print.h"

namespace smachac::backends::smach {
namespace {

void expectNoArguments(const tmpl::CallArgs& args, const char* what) {
  if (args.size() != 0) tmpl::fail(std::string("`") + what + "` takes no arguments");
}

}  // namespace

void registerPythonExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                              bool include_comments) {
  env.addFilter("pyrepr", [](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "pyrepr");
    if (input.isUndefined()) tmpl::fail(input.undefinedMessage());
    return tmpl::Value::string(tmpl::repr(input));
  });
  env.addTest("forced_string", [&converter](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "forced_string");
    return converter.isForcedString(input);
  });
  env.addGlobal("include_comments", tmpl::Value::boolean(include_comments));
}

}  // namespace smachac::backends::smach
