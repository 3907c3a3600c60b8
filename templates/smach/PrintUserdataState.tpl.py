{% block meta %}
name: PrintUserdataState
description: >
  A SMACH state that logs `userdata.<key>: <value>` for each of its input
  keys, in the order they are listed, then returns `succeeded`.
language: Python
framework: SMACH
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
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_PrintUserdataState' not in defined_headers %}
class PrintUserdataState(smach.State):
    """Logs every input key with its value, in the order given, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._keys = list(dict.fromkeys(input_keys))  # in order (SMACH keeps a set)

    def execute(self, userdata):
        for key in self._keys:
            smach.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'
{% do defined_headers.append('class_PrintUserdataState') %}
{% endif %}
{% endblock class_defs %}
