{% block meta %}
name: State
description: >
  What every FlexBE state template extends: the state's import (one per class,
  aliased on clashes), its userdata defaults (set on the parent container) and
  the `OperatableStateMachine.add(...)` line with transitions, autonomy and
  remapping. A state template sets `state_module` and `state_class` and
  `state_args` (the constructor's arguments); templates without a
  FlexBE library state also write an EventState class (class_defs).
language: Python
framework: FlexBE
type: None
tags: [core]
includes: []
extends: []
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
- - transitions:
      description: The sibling state or container outcome for each outcome.
      type: dict of str
- - autonomy:
      description: >
        The autonomy level of each outcome (Off, Low, High, Full or 0-3), or
        one level for all; default Off.
      type: dict of str
- - remapping:
      description: The parent's userdata key for each of the state's keys.
      type: dict of str
- - userdata:
      description: Userdata defaults set on the parent container, by key.
      type: dict
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import render_value, render_list, render_userdata, parent_var, layout, render_transitions, render_autonomy, remapping_argument, class_ref, import_state %}
{#- A state template sets `state_module`/`state_class` at its top level (empty for the
    default); by default the class is `class_name` in the behavior's states module. #}
{% set local_vars = ['default_module', 'state_module', 'state_class', 'state_args'] %}
{% set default_module = flexbe_package ~ '.' ~ flexbe_file ~ '_states' %}

{% block imports %}
{{ import_state(defined_headers, state_module or default_module, state_class or class_name) }}
{% endblock imports %}

{% block class_defs %}
{% endblock class_defs %}

{% block header %}
{% if userdata is defined %}
{{ render_userdata(parent_var(parent_template, parent_sm_name), userdata) }}
{% endif %}
{% endblock header %}

{% block body %}
{{ layout(defined_headers) }}
OperatableStateMachine.add({{ name | pyrepr }}, {{ class_ref(defined_headers, state_module or default_module, state_class or class_name) }}({{ state_args | default('') }}), {{ render_transitions(transitions if transitions is defined else {}) }}, {{ render_autonomy(transitions if transitions is defined else {}, autonomy) }}{{ remapping_argument(input_keys if input_keys is defined else [], output_keys if output_keys is defined else [], remapping) }})
{% endblock body %}
