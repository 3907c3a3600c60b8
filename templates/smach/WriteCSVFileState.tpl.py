{% block meta %}
name: WriteCSVFileState
description: >
  A SMACH state that writes the values of the `data_keys` userdata keys as
  one row of the CSV `file` (a list value spreads over several columns),
  after the `header` row when the state reads a `header` key; `aborted` when
  the file cannot be written. Runs its callbacks first.
language: Python
framework: SMACH
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
        the name of a function the program defines (in a custom template), a
        backtick-wrapped Python lambda of the userdata, or a portable `!expr`
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
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'csv') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_WriteCSVFileState' not in defined_headers %}
class WriteCSVFileState(smach.State):
    """Writes the values of the `data_keys` userdata keys as a row of the CSV `file`."""

    def __init__(self, delimiter=',', input_keys=['file', 'data_keys'], output_keys=[],
                 callbacks=[]):
        # `file` and `data_keys` are read whatever input keys the script lists, as on the
        # other targets.
        input_keys = ['file', 'data_keys'] + [key for key in input_keys
                                              if key not in ('file', 'data_keys')]
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._delimiter = delimiter
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        row = []
        for key in userdata.data_keys:
            value = userdata[key]
            row.extend(value if isinstance(value, (list, tuple)) else [value])
        try:
            with open(userdata.file, 'w', newline='') as stream:
                writer = csv.writer(stream, delimiter=self._delimiter)
                if 'header' in userdata:
                    writer.writerow(userdata.header)
                writer.writerow(row)
        except (IOError, OSError) as e:
            smach.logerr('Cannot write CSV file {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_WriteCSVFileState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{% set arguments = [] %}
{% if delimiter is defined %}{% do arguments.append('delimiter=' + delimiter | pyrepr) %}{% endif %}
{% if input_keys is defined %}{% do arguments.append(render_input_keys(input_keys, indent=0)) %}{% endif %}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif %}
{% if callbacks is defined %}{% do arguments.append(render_callbacks(name, uuid, callbacks, indent=0)) %}{% endif %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       WriteCSVFileState({{ arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
