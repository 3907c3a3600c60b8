{% block meta %}
name: ConditionalOutcomeState
description: >
  Runs its callbacks, one per outcome and keyed by it, then ends with the
  first outcome, in the order listed, whose key is set and true, and with
  `default` when none is; the choice is written to the `outcome` output key.
  The state is rt::ConditionalOutcomeState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- outcomes:
    description: >
      The outcomes, checked in order. The state also ends with `default` when
      no condition holds: list `default` (last) to give it a transition, as
      lint checks transitions against the listed outcomes.
    type: list of str
- - callbacks:
      description: >
        One callback per outcome, keyed by the outcome and run in the script's
        order, each computing from the userdata a truth value written to the
        key named like the outcome; without one, an outcome holds when its key
        is already set and true. A callback is
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
- default:
    description: The outcome when no condition holds.
    type: str
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_ConditionalOutcomeState' not in defined_headers %}
using rt::ConditionalOutcomeState;
{% do defined_headers.append('class_ConditionalOutcomeState') %}
{% endif %}
{% endblock class_defs %}
