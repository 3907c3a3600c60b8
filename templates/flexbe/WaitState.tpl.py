{% block meta %}
name: WaitState
description: >
  FlexBE's library state flexbe_states.wait_state.WaitState: waits
  `wait_time` seconds, then returns `done`.
language: Python
framework: FlexBE
type: WaitState
tags: [core]
includes: []
extends: []
variables:
- wait_time:
    description: The time to wait, in seconds.
    type: float
input_keys: []
output_keys: []
outcomes: [done]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_value %}
{% set state_module = 'flexbe_states.wait_state' %}
{% set state_class = 'WaitState' %}

{% set state_args = 'wait_time=' ~ render_value(wait_time) %}
