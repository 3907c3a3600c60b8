{% block meta %}
name: RandomOutcomeState
description: >
  Runs its callbacks, then ends with one of its outcomes chosen at random
  (seeded by --seed) and stores the choice in the `outcome` output key. The
  state is rt::RandomOutcomeState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - outcomes:
      description: The outcomes to choose from (default [succeeded]).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the outcome
        is chosen, each computing the value of its key from the userdata:
        the name of a C++ function the program defines (in a custom template), a
        backtick-wrapped C++ lambda taking rt::UserData&, or a portable `!expr`
        expression.
      type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: Other userdata keys the state writes (`outcome` is added).
      type: list of str
input_keys: []
output_keys:
- outcome:
    description: The chosen outcome.
    type: str
outcomes:
- succeeded:
    description: The only outcome when the state gives no `outcomes`.
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_RandomOutcomeState' not in defined_headers %}
using rt::RandomOutcomeState;
{% do defined_headers.append('class_RandomOutcomeState') %}
{% endif %}
{% endblock class_defs %}
