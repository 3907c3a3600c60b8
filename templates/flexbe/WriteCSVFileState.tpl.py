{% block meta %}
name: WriteCSVFileState
description: >
  Writes the values of the `data_keys` userdata keys as one row of the CSV
  `file` (a list value spreads over several columns), after the `header` row
  when the state reads a `header` key; `aborted` when the file cannot be
  written. Runs its callbacks first. FlexBE has no library equivalent: the
  template writes an EventState class into the behavior's states module.
language: Python
framework: FlexBE
type: WriteCSVFileState
tags: [core]
includes: []
extends: []
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
        a backtick-wrapped Python lambda of the userdata or a portable `!expr`
        expression (a function name is not a callback here).
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
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import file_state_args %}
{% set state_module = '' %}
{% set state_class = '' %}

{% set state_args = 'delimiter=' ~ (delimiter | default(',') | pyrepr) ~ ', '
    ~ file_state_args(['file', 'data_keys'], input_keys, output_keys, callbacks) %}

{% block class_defs %}
{% if 'class_WriteCSVFileState' not in defined_headers %}
import csv


class WriteCSVFileState(EventState):
    """
    Writes the values of the `data_keys` userdata keys as a row of the CSV `file`.

    -- delimiter    str     The column separator.
    -- input_keys   list    The userdata keys the state reads (`file`, `data_keys`, the data).
    -- output_keys  list    The userdata keys the callbacks write.
    -- callbacks    dict    Output key -> function of the userdata, run first.

    <= succeeded            The file is written.
    <= aborted              The file could not be written.
    """

    def __init__(self, delimiter, input_keys, output_keys, callbacks):
        super(WriteCSVFileState, self).__init__(outcomes=['succeeded', 'aborted'],
                                                input_keys=input_keys, output_keys=output_keys)
        self._delimiter = delimiter
        self._reads_header = 'header' in input_keys
        self._callbacks = callbacks

    def execute(self, userdata):
        for key, callback in self._callbacks.items():
            userdata[key] = callback(userdata)
        row = []
        for key in userdata.data_keys:
            value = userdata[key]
            row.extend(value if isinstance(value, (list, tuple)) else [value])
        try:
            with open(userdata.file, 'w', newline='') as stream:
                writer = csv.writer(stream, delimiter=self._delimiter)
                if self._reads_header and 'header' in userdata:
                    writer.writerow(userdata.header)
                writer.writerow(row)
        except (IOError, OSError) as e:
            Logger.logerr('Cannot write CSV file {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_WriteCSVFileState') %}
{% endif %}
{% endblock class_defs %}
