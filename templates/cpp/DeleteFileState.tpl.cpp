{% block meta %}
name: DeleteFileState
description: >
  Deletes the files the `file` input key names (a path or a glob pattern);
  `aborted` when one cannot be deleted or none exists. Runs its callbacks
  first (e.g. to compute the file name). The state is rt::DeleteFileState of
  the smachac runtime.
language: C++
framework: smachac runtime
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - input_keys:
      description: The userdata keys the state reads (`file` is added).
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the files
        are deleted (e.g. to compute the file name), each computing the value
        of its key from the userdata:
        the name of a C++ function the program defines (in a custom template), a
        backtick-wrapped C++ lambda taking rt::UserData&, or a portable `!expr`
        expression.
      type: dict of str
input_keys:
- file:
    description: The path or glob pattern of the files to delete.
    type: str
output_keys: []
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block class_defs %}
{{ super() }}
{% if 'class_DeleteFileState' not in defined_headers %}
using rt::DeleteFileState;
{% do defined_headers.append('class_DeleteFileState') %}
{% endif %}
{% endblock class_defs %}
