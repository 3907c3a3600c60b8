{% block meta %}
name: Step
description: >
  A custom C++ state template (an example for tests): adds `amount` to the
  userdata key `n`. Its helper function (defs) and its class (class_defs) are
  defined once per generated file; two libraries built with different amounts
  link into one program because -emit=library puts both in the library's
  namespace.
language: C++
framework: smachac runtime
type: State
tags: [test]
includes: []
extends:
- State
variables:
- amount:
    description: What one step adds to `n`.
    type: int
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block imports %}
{{ super() }}
{{ include_header(defined_headers, 'cstdint') }}
{{ include_header(defined_headers, 'string') }}
{% endblock imports %}

{% block defs %}
{{ super() }}
{% if 'def_step_amount' not in defined_headers %}
int64_t stepAmount() { return {{ amount }}; }
{% do defined_headers.append('def_step_amount') %}
{% endif %}
{% endblock defs %}

{% block class_defs %}
{{ super() }}
{% if 'class_Step' not in defined_headers %}
class Step : public rt::State {
 public:
  explicit Step(rt::StateSpec spec) : rt::State(std::move(spec)) {}
  std::string execute(rt::UserData& ud) override {
    ud.set("n", ud.get<int64_t>("n") + stepAmount());
    return "succeeded";
  }
};
{% do defined_headers.append('class_Step') %}
{% endif %}
{% endblock class_defs %}
