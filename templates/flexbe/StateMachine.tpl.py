{% block meta %}
name: StateMachine
description: >
  A FlexBE OperatableStateMachine container. It is declared before the root
  (deepest first, in the main_def buffer) as `_sm_<name>`, with its userdata
  defaults and its children added inside `with _sm_<name>:`; its parent adds
  it like a state.
language: Python
framework: FlexBE
type: Container
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes of the container.
    type: list of str
- - input_keys:
      description: The userdata keys the container reads from its parent.
      type: list of str
- - output_keys:
      description: The userdata keys the container writes to its parent.
      type: list of str
- - userdata:
      description: Userdata defaults of the container, by key.
      type: dict
- - transitions:
      description: The sibling state or parent outcome for each outcome.
      type: dict of str
- - autonomy:
      description: The autonomy level of each outcome (default Off).
      type: dict of str
- - remapping:
      description: The parent's userdata key for each of the container's keys.
      type: dict of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import container_args, render_userdata, parent_var, layout, render_transitions, render_autonomy, remapping_argument, outcome_layout %}
{#- Concurrence extends this template: it sets container_class and container_extra. #}
{% set local_vars = ['sm_var', 'container_class', 'container_extra'] %}
{% set sm_var = '_sm_' + name | lower %}

{% block main_def %}
{% if main_def %}
{{ main_def }}
{% endif %}
{{ outcome_layout(outcomes) }}
{{ sm_var }} = {{ container_class | default('OperatableStateMachine') }}({{ container_args(outcomes, input_keys, output_keys) }}{{ container_extra | default('') }})
{%- if userdata is defined %}
{{ render_userdata(sm_var, userdata) | trim }}
{%- endif %}
{%- if name in header and header[name] %}
{{ header[name] | trim }}
{%- endif %}

with {{ sm_var }}:
    {{ body | indent(4) }}
{% endblock main_def %}

{% block header %}
{% endblock header %}

{% block body %}
{{ layout(defined_headers) }}
OperatableStateMachine.add({{ name | pyrepr }}, {{ sm_var }}, {{ render_transitions(transitions if transitions is defined else {}) }}, {{ render_autonomy(transitions if transitions is defined else {}, autonomy) }}{{ remapping_argument(input_keys if input_keys is defined else [], output_keys if output_keys is defined else [], remapping) }})
{% endblock body %}
