{% block meta %}
name: WriteCSVFileState
description: >
  Writes the values of the `data_keys` userdata keys as one row of the CSV
  `file` (a list value spreads over several columns), after the `header` row
  when the state reads a `header` key; the file is written as Python's
  csv.writer writes it. `aborted` when it cannot be written. The state is
  rt::WriteCSVFileState of the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- input_keys:
    description: The userdata keys the state reads (file, data_keys and the data).
    type: list of str
- - output_keys:
      description: The userdata keys the callbacks write.
      type: list of str
- - callbacks:
      description: Callbacks by output key (C++ lambdas taking rt::UserData&), e.g. to prepare the data.
      type: dict of str
- - delimiter:
      description: The column separator (default `,`).
      type: str
input_keys:
- file:
    description: The path of the CSV file.
    type: str
- data_keys:
    description: The userdata keys to write, one row.
    type: list of str
output_keys: []
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_WriteCSVFileState' not in defined_headers %}
using rt::WriteCSVFileState;
{% do defined_headers.append('class_WriteCSVFileState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- if include_comments %}
// {{ name | cppcomment }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, (delimiter | default(',') | cppstr) + ', ' + render_state_arguments(name, uuid, input_keys, output_keys, callbacks, outcomes), transitions, remapping) }}
{% endblock body %}
