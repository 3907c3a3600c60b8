{% block meta %}
name: Greeter
description: >
  A custom C++ state template (an example for tests): defines its class once in
  class_defs and adds the state with an extra constructor argument, `who`.
language: C++
framework: smachac runtime
type: State
tags: [test]
includes: []
extends:
- State
variables:
- who:
    description: Whom to greet.
    type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block imports %}
{{ super() }}
{{ include_header(defined_headers, 'iostream') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_Greeter' not in defined_headers %}
class Greeter : public rt::State {
 public:
  Greeter(rt::StateSpec spec, std::string who) : rt::State(std::move(spec)), who_(std::move(who)) {}
  std::string execute(rt::UserData&) override {
    std::cout << "hello, " << who_ << "\n";
    return "succeeded";
  }

 private:
  std::string who_;
};
{% do defined_headers.append('class_Greeter') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, render_spec(outcomes, input_keys, output_keys) + ', ' + (who | cppstr), transitions, remapping) }}
{% endblock body %}
