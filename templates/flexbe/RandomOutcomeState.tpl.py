{% block meta %}
name: RandomOutcomeState
description: >
  Runs its callbacks, then ends with one of its outcomes chosen at random and
  stores the choice in the `outcome` output key. FlexBE has no library
  equivalent: the template writes an EventState class into the behavior's
  states module.
language: Python
framework: FlexBE
type: RandomOutcomeState
tags: [core]
includes: []
extends: []
variables:
- - outcomes:
      description: The outcomes to choose from (default [succeeded]).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the outcome
        is chosen, each computing the value of its key from the userdata:
        a backtick-wrapped Python lambda of the userdata or a portable `!expr`
        expression (a function name is not a callback here).
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
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_list, render_callbacks %}
{% set state_module = '' %}
{% set state_class = '' %}

{# As for the other targets: each callback's key is an output key, and so is `outcome`. #}
{% set chosen_callbacks = callbacks if callbacks is defined else {} %}
{% set written = (output_keys if output_keys is defined else []) | list %}
{% for key in chosen_callbacks if key not in written %}{% do written.append(key) %}{% endfor %}
{% if 'outcome' not in written %}{% do written.append('outcome') %}{% endif %}
{# Without `outcomes`, the state's only outcome is `succeeded`, as on the other targets. #}
{% set state_args = 'outcomes=' ~ render_list(outcomes if outcomes is defined else ['succeeded'])
    ~ ', callbacks=' ~ render_callbacks(chosen_callbacks)
    ~ ', input_keys=' ~ render_list(input_keys if input_keys is defined else [])
    ~ ', output_keys=' ~ render_list(written) %}

{% block class_defs %}
{% if 'class_RandomOutcomeState' not in defined_headers %}
class RandomOutcomeState(EventState):
    """
    Runs its callbacks on the userdata, in order, then returns one of its
    outcomes chosen at random and stores it in `outcome`.

    -- outcomes     list    The outcomes to choose from.
    -- callbacks    dict    Output key -> function of the userdata.
    -- input_keys   list    The userdata keys the callbacks read.
    -- output_keys  list    The userdata keys written, `outcome` included.

    #> outcome      str     The chosen outcome.

    <= (any)                One of the outcomes.
    """

    def __init__(self, outcomes, callbacks, input_keys, output_keys):
        super(RandomOutcomeState, self).__init__(outcomes=outcomes, input_keys=input_keys,
                                                 output_keys=output_keys)
        self._callbacks = callbacks

    def execute(self, userdata):
        import random
        for key, callback in self._callbacks.items():
            userdata[key] = callback(userdata)
        outcome = random.choice(sorted(self._outcomes))
        userdata.outcome = outcome
        return outcome
{% do defined_headers.append('class_RandomOutcomeState') %}
{% endif %}
{% endblock class_defs %}
