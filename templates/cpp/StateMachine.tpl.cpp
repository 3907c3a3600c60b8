{% block meta %}
name: StateMachine
description: >
  A StateMachine container (rt::StateMachine): its child states run one after
  the other, following their transitions. The container is added to its
  parent inside its own C++ scope as `sm_<name>` (a reference), then its
  userdata and its children's userdata are set and its children added.
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
{% from "Utils.tpl.cpp" import render_outcomes, render_input_keys, render_output_keys, render_container_contents %}
{# Exported: later states at this level see the last container's variable name. #}
{% set sm_name = 'sm_' + name | lower %}

{% block upper_comments %}
// BEGIN: {{ name | cppcomment }} (StateMachine)
{% endblock upper_comments %}

{% block body %}
{%- if include_comments %}
// BEGIN: {{ name | cppcomment }} (StateMachine)
{%- endif %}
{%- set fields = [render_outcomes(outcomes)] %}
{%- if input_keys is defined %}{% do fields.append(render_input_keys(input_keys)) %}{% endif %}
{%- if output_keys is defined %}{% do fields.append(render_output_keys(output_keys)) %}{% endif %}
{{ render_container_contents(name, sm_name, 'rt::StateMachine', 'rt::CStringSpec{' + fields | join(', ') + '}', parent_sm_name, parent_type, header, userdata, header_userdata, body, transitions, remapping) }}
{%- if include_comments %}
// END: {{ name | cppcomment }}
{%- endif %}
{% endblock body %}

{% block lower_comments %}
// END: {{ name | cppcomment }}
{% endblock lower_comments %}
