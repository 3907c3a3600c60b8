// Python escaping and the forced-string test for the SMACH and FlexBE templates.
#include "backends/smach/python_extensions.h"

#include "backends/smach/python_code.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::backends::smach {
namespace {

void expectNoArguments(const tmpl::CallArgs& args, const char* what) {
  if (args.size() != 0) tmpl::fail(std::string("`") + what + "` takes no arguments");
}

/// Registers `name` as a filter from a defined value to the text `convert` gives.
template <typename Convert>
void addTextFilter(tmpl::Environment& env, const char* name, Convert convert) {
  env.addFilter(name, [name, convert](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, name);
    if (input.isUndefined()) tmpl::fail(input.undefinedMessage());
    return tmpl::Value::string(convert(input));
  });
}

std::string textOf(const tmpl::Value& value) {
  return value.isString() ? value.s() : tmpl::str(value);
}

}  // namespace

void registerPythonExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                              bool include_comments) {
  addTextFilter(env, "pyrepr", [](const tmpl::Value& v) { return tmpl::repr(v); });
  addTextFilter(env, "pyliteral", pythonLiteral);
  addTextFilter(env, "pycode", pythonCode);
  addTextFilter(env, "pycomment", [](const tmpl::Value& v) { return pythonComment(textOf(v)); });
  addTextFilter(env, "pyident", [](const tmpl::Value& v) { return identifierPart(textOf(v)); });
  env.addTest("forced_string", [&converter](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "forced_string");
    return converter.isForcedString(input);
  });
  env.addGlobal("include_comments", tmpl::Value::boolean(include_comments));
}

}  // namespace smachac::backends::smach
