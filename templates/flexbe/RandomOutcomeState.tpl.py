{% block meta %}
name: RandomOutcomeState
description: >
  Returns one of its outcomes at random. FlexBE has no library equivalent:
  the template writes an EventState class into the behavior's states module.
language: Python
framework: FlexBE
type: RandomOutcomeState
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes to choose from.
    type: list of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_list %}
{% set state_module = '' %}
{% set state_class = '' %}

{% set state_args = 'outcomes=' ~ render_list(outcomes) %}

{% block class_defs %}
{% if 'class_RandomOutcomeState' not in defined_headers %}
class RandomOutcomeState(EventState):
    """
    Returns one of its outcomes, chosen at random.

    -- outcomes list    The outcomes to choose from.

    <= (any)            One of the outcomes.
    """

    def __init__(self, outcomes):
        super(RandomOutcomeState, self).__init__(outcomes=outcomes)

    def execute(self, userdata):
        import random
        return random.choice(sorted(self._outcomes))
{% do defined_headers.append('class_RandomOutcomeState') %}
{% endif %}
{% endblock class_defs %}
