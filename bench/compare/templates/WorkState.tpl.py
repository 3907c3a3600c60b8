{% block meta %}
name: WorkState
description: A leaf state of the benchmark's generated scripts; does nothing and succeeds.
language: Python
framework: SMACH
type: State
tags: [bench]
includes: []
extends:
- State
variables:
- - input_keys:
      description: The userdata keys it reads.
      type: list of str
- - output_keys:
      description: The userdata keys it writes.
      type: list of str
- - outcomes:
      description: Its outcomes; it always returns the first.
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_WorkState' not in defined_headers %}
class WorkState(smach.State):
    """A benchmark leaf: returns its first outcome."""

    def __init__(self, input_keys=[], output_keys=[], outcomes=['succeeded', 'aborted']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._outcome = outcomes[0]

    def execute(self, userdata):
        return self._outcome
{% do defined_headers.append('class_WorkState') %}
{% endif %}
{% endblock class_defs %}
