{% block meta %}
name: LogState
description: >
  Prints `text` on a line of its own, then returns `done`: FlexBE's LogState
  under the same name, variables and outcome (`severity` is accepted for
  scripts written for FlexBE and does not change the output). The state is
  rt::LogState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- text:
    description: The message.
    type: str
- - severity:
      description: FlexBE's Logger.REPORT_* level; not used here.
      type: str
input_keys: []
output_keys: []
outcomes: [done]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_LogState' not in defined_headers %}
using rt::LogState;
{% do defined_headers.append('class_LogState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- if include_comments %}
// {{ name | cppcomment }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, (text | string | cppstr) + ', ' + render_spec(outcomes, input_keys, output_keys), transitions, remapping) }}
{% endblock body %}
