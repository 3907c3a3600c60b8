{% block meta %}
name: RandomOutcomeState
description: >
  A SMACH state that runs its callbacks, then ends with one of its outcomes
  chosen at random and stores the choice in the `outcome` output key. Without
  callbacks it gets a default one (it also draws an outcome into `outcome`);
  like every template global, that default stays set for the states after it.
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - outcomes:
      description: The outcomes to choose from (default [succeeded]).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the outcome
        is chosen, each computing the value of its key from the userdata:
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
- succeeded:
    description: The only outcome when the state gives no `outcomes`.
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}
{# A global on purpose: SMACHA's template sets `callbacks` at the top level, so it reaches the
   following states, and scripts written for SMACHA expect that. #}
{% if callbacks is not defined %}
{% set callbacks = {'outcome': '`lambda ud: random.choice(' + ((outcomes if outcomes is defined else ['succeeded']) | list | string) + ')`'} %}
{% endif %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'random') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_RandomOutcomeState' not in defined_headers %}
class RandomOutcomeState(smach.State):
    """Runs its callbacks, then ends with one of its outcomes chosen at random."""

    def __init__(self, input_keys=[], output_keys=['outcome'], callbacks=[], outcomes=['succeeded']):
        if 'outcome' not in output_keys:
            output_keys = list(output_keys) + ['outcome']
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._choices = sorted(outcomes)
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        outcome = random.choice(self._choices)
        userdata.outcome = outcome
        return outcome
{% do defined_headers.append('class_RandomOutcomeState') %}
{% endif %}
{% endblock class_defs %}
