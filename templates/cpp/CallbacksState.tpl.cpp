{% block meta %}
name: CallbacksState
description: >
  Runs its callbacks on the userdata, in the script's order, each writing the
  output key it is listed under, then returns `succeeded`. The state is
  rt::CallbacksState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- callbacks:
    description: >
      Callbacks by output key, run in the script's order, each computing the
      value of its key from the userdata:
      the name of a C++ function the program defines (in a custom template), a
      backtick-wrapped C++ lambda taking rt::UserData&, or a portable `!expr`
      expression.
    type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_CallbacksState' not in defined_headers %}
using rt::CallbacksState;
{% do defined_headers.append('class_CallbacksState') %}
{% endif %}
{% endblock class_defs %}
