{% block meta %}
name: ConditionalOutcomeState
description: >
  A SMACH state that ends with the first of its outcomes whose callback (named
  like the outcome) returns a true value, and with `default` when none does.
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- outcomes:
    description: >
      The outcomes, checked in order. The state also ends with `default` when
      no callback holds: list `default` (last) to give it a transition, as
      lint checks transitions against the listed outcomes.
    type: list of str
- callbacks:
    description: >
      One callback per outcome, keyed by the outcome: a function name or a
      backtick-wrapped lambda expression returning a truth value.
    type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
input_keys: []
output_keys:
- outcome:
    description: The chosen outcome.
    type: str
outcomes:
- default:
    description: The outcome when no callback returns a true value.
    type: str
{% endblock meta %}
{% from "Utils.tpl.py" import render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_ConditionalOutcomeState' not in defined_headers %}
class ConditionalOutcomeState(smach.State):
    """Ends with the first outcome whose callback output is true, else `default`."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=[]):
        # Each condition's callback writes the key named like the outcome, which execute()
        # then reads: it is both an output and an input key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions if o not in output_keys]
        if 'outcome' not in output_keys:
            output_keys.append('outcome')
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=self._conditions + ['default'])
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'
{% do defined_headers.append('class_ConditionalOutcomeState') %}
{% endif %}
{% endblock class_defs %}
