{% block meta %}
name: CallbacksState
description: >
  A SMACH state that runs its callbacks on the userdata, in the script's
  order, each writing the output key it is listed under, then returns
  `succeeded`.
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- callbacks:
    description: >
      Callbacks by output key, run in the script's order, each computing the
      value of its key from the userdata:
      the name of a function the program defines (in a custom template), a
      backtick-wrapped Python lambda of the userdata, or a portable `!expr`
      expression.
    type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% from "Utils.tpl.py" import render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_CallbacksState' not in defined_headers %}
class CallbacksState(smach.State):
    """Runs its callbacks on the userdata, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        return 'succeeded'
{% do defined_headers.append('class_CallbacksState') %}
{% endif %}
{% endblock class_defs %}
