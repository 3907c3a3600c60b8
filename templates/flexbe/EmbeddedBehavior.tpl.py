{% block meta %}
name: EmbeddedBehavior
description: >
  Another FlexBE behavior used as a state of this one: its module is imported,
  the base template declares it in __init__ (`self.add_behavior`) and the
  parent adds `self.use_behavior(<Name>SM, '<id>', parameters={...})`. The
  FlexBE target puts this template in place of every sub-script state it
  embeds as a behavior.
language: Python
framework: FlexBE
type: EmbeddedBehavior
tags: [core]
includes: []
extends: []
variables:
- behavior_name:
    description: The embedded behavior's name.
    type: str
- behavior_id:
    description: The state's path in this behavior, '/'-separated.
    type: str
- - behavior_parameters:
      description: The values passed to the embedded behavior's parameters, by name.
      type: dict
- - transitions:
      description: The sibling state or parent outcome for each outcome.
      type: dict of str
- - autonomy:
      description: The autonomy level of each outcome (default Off).
      type: dict of str
- - remapping:
      description: The parent's userdata key for each of the behavior's keys.
      type: dict of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_value, layout, render_transitions, render_autonomy, remapping_argument, class_ref, import_state, behavior_file, class_prefix %}
{% set state_module = flexbe_package ~ '.' ~ behavior_file(behavior_name) ~ '_sm' %}
{% set state_class = class_prefix(behavior_name) ~ 'SM' %}

{% block body %}
{{ layout(defined_headers) }}
OperatableStateMachine.add({{ name | pyrepr }}, self.use_behavior({{ class_ref(defined_headers, state_module, state_class) }}, {{ behavior_id | pyrepr }}
{%- if behavior_parameters is defined and behavior_parameters %}, parameters={{ '{' }}
{%- for key, value in behavior_parameters.items() %}{{ key | pyrepr }}: {{ render_value(value) }}{% if not loop.last %}, {% endif %}{% endfor %}{{ '}' }}
{%- endif %}), {{ render_transitions(transitions if transitions is defined else {}) }}, {{ render_autonomy(transitions if transitions is defined else {}, autonomy) }}{{ remapping_argument(input_keys if input_keys is defined else [], output_keys if output_keys is defined else [], remapping) }})
{% endblock body %}
