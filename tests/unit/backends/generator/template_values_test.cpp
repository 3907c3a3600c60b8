// IR values as template values, and the view model of a state.
#include "backends/generator/template_values.h"

#include <doctest/doctest.h>

#include "backends/generator/state_variables.h"
#include "backends/tmpl/values/value_print.h"

namespace smachac::generator {
namespace {

TEST_CASE("values convert like Python's, expressions keep their backticks") {
  ValueConverter c;
  ir::Value list =
      ir::Value::list({ir::Value::integer(1), ir::Value::real(0.5), ir::Value::boolean(true),
                       ir::Value::null(), ir::Value::string("x")});
  CHECK(tmpl::repr(c.convert(list)) == "[1, 0.5, True, None, 'x']");
  CHECK(c.convert(ir::Value::expression("lambda ud: 1")).s() == "`lambda ud: 1`");
  ir::Value map =
      ir::Value::map({{"b", {}, ir::Value::integer(2)}, {"a", {}, ir::Value::integer(1)}});
  CHECK(tmpl::repr(c.convert(map)) == "{'b': 2, 'a': 1}");
}

TEST_CASE("a !str string is known by identity, an equal plain string is not") {
  ValueConverter c;
  ir::Value forced = ir::Value::string("1.5");
  forced.forced_string = true;
  tmpl::Value f = c.convert(forced);
  tmpl::Value plain = c.convert(ir::Value::string("1.5"));
  CHECK(c.isForcedString(f));
  tmpl::Value copy = f;  // templates pass values by reference
  CHECK(c.isForcedString(copy));
  CHECK_FALSE(c.isForcedString(plain));
  CHECK_FALSE(c.isForcedString(tmpl::Value::integer(1)));
}

TEST_CASE("a state's template variables: given keys only, a script `name` key wins") {
  ValueConverter c;
  ir::State state;
  state.name = {"FOO", {}};
  state.template_name = ir::Name{"PrintUserdataState", {}};
  state.input_keys = {{"a", {}}};
  state.transitions.push_back({{"succeeded", {}}, {"BAR", {}}, ir::TargetKind::Sibling, {}});
  ir::Argument callback;
  callback.key.text = "a";
  callback.value = ir::Value::expression("lambda ud: 2");
  state.callbacks.push_back(callback);
  tmpl::Value vars = stateVariables(state, "u", c);
  CHECK(vars.dict().findString("class_name")->s() == "PrintUserdataState");
  CHECK(vars.dict().findString("name")->s() == "FOO");
  CHECK(vars.dict().findString("uuid")->s() == "u");
  CHECK(tmpl::repr(*vars.dict().findString("input_keys")) == "['a']");
  CHECK(tmpl::repr(*vars.dict().findString("transitions")) == "{'succeeded': 'BAR'}");
  CHECK(tmpl::repr(*vars.dict().findString("callbacks")) == "{'a': '`lambda ud: 2`'}");
  CHECK(vars.dict().findString("outcomes") == nullptr);
  CHECK(vars.dict().findString("userdata") == nullptr);
  ir::Argument renamed;
  renamed.key.text = "name";
  renamed.value = ir::Value::string("OTHER");
  state.args.push_back(renamed);
  CHECK(stateVariables(state, "u", c).dict().findString("name")->s() == "OTHER");
}

TEST_CASE("names with the same text share one string; a forced string is never shared") {
  ValueConverter c;
  std::vector<ir::Name> first = {{"succeeded", {}}, {"aborted", {}}};
  std::vector<ir::Name> second = {{"succeeded", {}}};
  tmpl::Value a = c.names(first);
  tmpl::Value b = c.names(second);
  CHECK(tmpl::repr(a) == "['succeeded', 'aborted']");
  CHECK(a.list().items()[0].identity() == b.list().items()[0].identity());
  CHECK(c.literal("outcomes").identity() == c.literal("outcomes").identity());
  ir::Value forced = ir::Value::string("succeeded");
  forced.forced_string = true;
  tmpl::Value f = c.convert(forced);
  CHECK(c.isForcedString(f));
  CHECK_FALSE(c.isForcedString(c.names(second).list().items()[0]));
}

}  // namespace
}  // namespace smachac::generator
