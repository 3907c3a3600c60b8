{% block meta %}
name: OtherWaitState
description: A state class named WaitState from another package (import clash test).
language: Python
framework: FlexBE
type: OtherWaitState
tags: [test]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: [done]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% set state_module = 'my_flexbe_states.wait_state' %}
{% set state_class = 'WaitState' %}
{% set state_args = '' %}
