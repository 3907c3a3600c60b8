{% block meta %}
name: CallbacksState
description: >
  A SMACH state that only runs its callbacks on the userdata, e.g. lambda
  expressions that compute output keys from input keys, and then succeeds.
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
      Callbacks by output key: function names or backtick-wrapped lambda
      expressions.
    type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write.
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
