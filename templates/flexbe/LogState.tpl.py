{% block meta %}
name: LogState
description: >
  FlexBE's library state flexbe_states.log_state.LogState: logs `text` at
  `severity` (Logger.REPORT_HINT by default), then returns `done`.
language: Python
framework: FlexBE
type: LogState
tags: [core]
includes: []
extends: []
variables:
- text:
    description: The message.
    type: str
- - severity:
      description: A Logger.REPORT_* level, e.g. `Logger.REPORT_INFO`.
      type: str
input_keys: []
output_keys: []
outcomes: [done]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_value %}
{% set state_module = 'flexbe_states.log_state' %}
{% set state_class = 'LogState' %}

{% set state_args = 'text=' ~ render_value(text) ~ ', severity=' ~ (severity | default('Logger.REPORT_HINT')) %}
