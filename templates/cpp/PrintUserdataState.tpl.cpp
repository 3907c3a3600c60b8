{% block meta %}
name: PrintUserdataState
description: >
  Prints `userdata.<key>: <value>` for each of its input keys, in the order
  they are listed, then returns `succeeded`. The state is
  rt::PrintUserdataState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - input_keys:
      description: The userdata keys to print, in this order.
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_PrintUserdataState' not in defined_headers %}
using rt::PrintUserdataState;
{% do defined_headers.append('class_PrintUserdataState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- if include_comments %}
// {{ name | cppcomment }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, render_spec(outcomes, input_keys, output_keys), transitions, remapping) }}
{% endblock body %}
