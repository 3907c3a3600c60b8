{% block meta %}
name: ConditionalOutcomeState
description: >
  A SMACH state that runs its callbacks, one per outcome and keyed by it, then
  ends with the first outcome, in the order listed, whose key is set and
  true, and with `default` when none is; the choice is written to the
  `outcome` output key.
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
      no condition holds: list `default` (last) to give it a transition, as
      lint checks transitions against the listed outcomes.
    type: list of str
- - callbacks:
      description: >
        One callback per outcome, keyed by the outcome and run in the script's
        order, each computing from the userdata a truth value written to the
        key named like the outcome; without one, an outcome holds when its key
        is already set and true. A callback is
        the name of a function the program defines (in a custom template), a
        backtick-wrapped Python lambda of the userdata, or a portable `!expr`
        expression.
      type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: Other userdata keys the state writes (`outcome` is added).
      type: list of str
input_keys: []
output_keys:
- outcome:
    description: The chosen outcome.
    type: str
outcomes:
- default:
    description: The outcome when no condition holds.
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
