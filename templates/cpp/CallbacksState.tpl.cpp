{% block meta %}
name: CallbacksState
description: >
  Runs its callbacks on the userdata (each writes its output key), then succeeds.
  The state is rt::CallbacksState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - outcomes:
      description: The outcomes of the state.
      type: list of str
- - input_keys:
      description: The userdata keys the state reads.
      type: list of str
- - output_keys:
      description: The userdata keys the state writes.
      type: list of str
- - callbacks:
      description: Callbacks by output key (C++ lambdas taking rt::UserData&, or function names).
      type: dict of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_CallbacksState' not in defined_headers %}
using rt::CallbacksState;
{% do defined_headers.append('class_CallbacksState') %}
{% endif %}
{% endblock class_defs %}
