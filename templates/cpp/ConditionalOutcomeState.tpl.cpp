{% block meta %}
name: ConditionalOutcomeState
description: >
  Runs its callbacks (one per outcome, keyed by the outcome), then ends with the first outcome whose key holds true, else `default`.
  The state is rt::ConditionalOutcomeState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - outcomes:
      description: >
        The outcomes, checked in order. The state also ends with `default` when
        no callback holds: list `default` (last) to give it a transition, as
        lint checks transitions against the listed outcomes.
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
{% if 'class_ConditionalOutcomeState' not in defined_headers %}
using rt::ConditionalOutcomeState;
{% do defined_headers.append('class_ConditionalOutcomeState') %}
{% endif %}
{% endblock class_defs %}
