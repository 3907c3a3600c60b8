{% block meta %}
name: SleepState
description: >
  Sleeps for `time` seconds, then succeeds. Declared with `outcomes: [succeeded,
  preempted]`, it wakes at once on a preempt request and returns `preempted` (as SMACH, a
  state returns only the outcomes it declares).
  The state is rt::SleepState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- time:
    description: How long to sleep, in seconds.
    type: float
    units: s
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_SleepState' not in defined_headers %}
using rt::SleepState;
{% do defined_headers.append('class_SleepState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- if include_comments %}
// {{ name | cppcomment }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, (time | float | cppvalue) + ', ' + render_spec(outcomes, input_keys, output_keys), transitions, remapping) }}
{% endblock body %}
