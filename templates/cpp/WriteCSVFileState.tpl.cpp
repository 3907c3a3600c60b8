{% block meta %}
name: WriteCSVFileState
description: >
  Writes the values of the `data_keys` userdata keys as one row of the CSV
  `file` (a list value spreads over several columns), after the `header` row
  when the state reads a `header` key; `aborted` when the file cannot be
  written. Runs its callbacks first. The file is written as Python's
  csv.writer writes it. The state is rt::WriteCSVFileState of the smachac
  runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- input_keys:
    description: >
      The userdata keys the state reads: the keys `data_keys` names, and
      `header` for a first row (`file` and `data_keys` are added).
    type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the file is
        written (e.g. to prepare the data), each computing the value of its
        key from the userdata:
        the name of a C++ function the program defines (in a custom template), a
        backtick-wrapped C++ lambda taking rt::UserData&, or a portable `!expr`
        expression.
      type: dict of str
- - delimiter:
      description: The column separator, one character (default `,`).
      type: str
input_keys:
- file:
    description: The path of the CSV file.
    type: str
- data_keys:
    description: The userdata keys whose values form the row, in order.
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
