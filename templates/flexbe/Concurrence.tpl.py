{% block meta %}
name: Concurrence
description: >
  A FlexBE ConcurrencyContainer (from a SMACH Concurrence), declared like a
  StateMachine (which it extends). Its conditions come from the outcome_map,
  one conjunction per outcome, in the order SMACH 2.5 prefers them (more
  conditions first, then by outcome; none for an empty entry); the first
  satisfied wins. FlexBE has no
  default outcome: the FlexBE target sets `default_conditions`, every
  combination of the children's outcomes, each a list of [child, outcome],
  which lead to default_outcome after the outcome_map's conditions.
language: Python
framework: FlexBE
type: Container
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes of the container.
    type: list of str
- - input_keys:
      description: The userdata keys the container reads from its parent.
      type: list of str
- - output_keys:
      description: The userdata keys the container writes to its parent.
      type: list of str
- - userdata:
      description: Userdata defaults of the container, by key.
      type: dict
- - transitions:
      description: The sibling state or parent outcome for each outcome.
      type: dict of str
- - autonomy:
      description: The autonomy level of each outcome (default Off).
      type: dict of str
- - outcome_map:
      description: For each outcome, the child outcomes that must all have occurred.
      type: dict
- - remapping:
      description: The parent's userdata key for each of the container's keys.
      type: dict of str
- - default_conditions:
      description: >
        Set by the FlexBE target: the combinations of the children's outcomes
        that lead to default_outcome, each a list of [child, outcome].
      type: list
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "StateMachine.tpl.py" %}
{% from "Utils.tpl.py" import render_conditions %}
{% set container_class = 'ConcurrencyContainer' %}
{% set container_extra = ', ' ~ render_conditions(outcome_map if outcome_map is defined else {}, default_outcome if default_outcome is defined else '', default_conditions if default_conditions is defined else []) %}
