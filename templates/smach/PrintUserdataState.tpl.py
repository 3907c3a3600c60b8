{% block meta %}
name: PrintUserdataState
description: A SMACH state that logs the value of each of its input keys, then succeeds.
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - input_keys:
      description: The userdata keys to print.
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
    """Logs every input key with its value, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)

    def execute(self, userdata):
        for key in sorted(self.get_registered_input_keys()):
            smach.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'
{% do defined_headers.append('class_PrintUserdataState') %}
{% endif %}
{% endblock class_defs %}
