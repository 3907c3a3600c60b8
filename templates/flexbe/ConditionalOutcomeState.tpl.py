{% block meta %}
name: ConditionalOutcomeState
description: >
  Runs its callbacks, one per outcome and keyed by it, then ends with the
  first outcome, in the order listed, whose key is set and true, and with
  `default` when none is; the choice is written to the `outcome` output key.
  FlexBE has no library equivalent: the template writes an EventState class
  into the behavior's states module.
language: Python
framework: FlexBE
type: ConditionalOutcomeState
tags: [core]
includes: []
extends: []
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
- default:
    description: The outcome when no condition holds.
    type: str
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_list, render_callbacks %}
{% set state_module = '' %}
{% set state_class = '' %}

{# As for the other targets: each callback's key is an output key, declared or not (the class
   adds the outcomes' keys itself). #}
{% set chosen_callbacks = callbacks if callbacks is defined else {} %}
{% set written = (output_keys if output_keys is defined else []) | list %}
{% for key in chosen_callbacks if key not in written and key not in outcomes %}{% do written.append(key) %}{% endfor %}
{% set state_args = 'outcomes=' ~ render_list(outcomes)
    ~ ', callbacks=' ~ render_callbacks(chosen_callbacks)
    ~ ', input_keys=' ~ render_list(input_keys if input_keys is defined else [])
    ~ ', output_keys=' ~ render_list(written) %}

{% block class_defs %}
{% if 'class_ConditionalOutcomeState' not in defined_headers %}
class ConditionalOutcomeState(EventState):
    """
    Runs its callbacks, then ends with the first outcome whose key is set and true, else
    `default`; writes the choice to `outcome`.

    -- outcomes     list    The outcomes, checked in order.
    -- callbacks    dict    Outcome -> function of the userdata returning a truth value.
    -- input_keys   list    The userdata keys the callbacks read.
    -- output_keys  list    Other userdata keys the state writes.

    #> outcome      str     The chosen outcome.

    <= (any)                The first outcome that holds, or `default`.
    """

    def __init__(self, outcomes, callbacks, input_keys, output_keys):
        # A condition's callback writes the key named like the outcome, which execute() then
        # reads: it is both an input and an output key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions + ['outcome']
                                           if o not in output_keys]
        super(ConditionalOutcomeState, self).__init__(outcomes=self._conditions + ['default'],
                                                      input_keys=input_keys,
                                                      output_keys=output_keys)
        self._callbacks = callbacks

    def execute(self, userdata):
        for key, callback in self._callbacks.items():
            userdata[key] = callback(userdata)
        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'
{% do defined_headers.append('class_ConditionalOutcomeState') %}
{% endif %}
{% endblock class_defs %}
