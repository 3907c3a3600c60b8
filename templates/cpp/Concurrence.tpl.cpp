{% block meta %}
name: Concurrence
description: >
  A Concurrence container (rt::Concurrence): its child states run in
  parallel. The outcome map chooses the container's outcome from the
  children's outcomes; the default outcome applies when no entry matches. As
  in SMACH, the container waits for every child (early_exit off).
language: C++
framework: smachac runtime
type: Container
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes of the container.
    type: list of str
- default_outcome:
    description: The outcome when no outcome map entry matches.
    type: str
- outcome_map:
    description: >
      For each container outcome, the outcome every listed child must end with
      for the container to end with it.
    type: dict of dict of str
- - input_keys:
      description: The userdata keys the container reads from its parent.
      type: list of str
- - output_keys:
      description: The userdata keys the container writes to its parent.
      type: list of str
- - userdata:
      description: Userdata values of the container, by key.
      type: dict
- - transitions:
      description: The sibling state or parent outcome for each outcome.
      type: dict of str
- - remapping:
      description: The parent's userdata key for each of the container's keys.
      type: dict of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.cpp" import render_outcomes, render_outcome_map, render_input_keys, render_output_keys, render_container_contents %}
{# Exported: later states at this level see the last container's variable name. #}
{% set sm_name = 'sm_' + name | lower %}

{% block upper_comments %}
// BEGIN: {{ name | cppcomment }} (Concurrence)
{% endblock upper_comments %}

{% block body %}
{%- if include_comments %}
// BEGIN: {{ name | cppcomment }} (Concurrence)
{%- endif %}
{%- set fields = [render_outcomes(outcomes), '.default_outcome = ' + (default_outcome | cppstr if default_outcome is defined else '""')] %}
{%- if outcome_map is defined %}{% do fields.append(render_outcome_map(outcome_map)) %}{% endif %}
{%- if input_keys is defined %}{% do fields.append(render_input_keys(input_keys)) %}{% endif %}
{%- if output_keys is defined %}{% do fields.append(render_output_keys(output_keys)) %}{% endif %}
{%- do fields.append('.early_exit = false') %}
{{ render_container_contents(name, sm_name, 'rt::Concurrence', 'rt::CStringConcurrenceSpec{' + fields | join(', ') + '}', parent_sm_name, parent_type, header, userdata, header_userdata, body, transitions, remapping) }}
{%- if include_comments %}
// END: {{ name | cppcomment }}
{%- endif %}
{% endblock body %}

{% block lower_comments %}
// END: {{ name | cppcomment }}
{% endblock lower_comments %}
