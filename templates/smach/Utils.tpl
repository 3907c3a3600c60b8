{% block meta %}
name: Utils
description: >
  The 2017 name of the macro library (templates written for SMACHA 2017 import
  from "Utils.tpl"). Every macro forwards to Utils.tpl.py; the two callback
  macros keep their 2017 parameters and names callbacks <key>_<state>_lambda_cb.
language: Python
framework: SMACH
type: None
tags: [core]
includes:
- Utils.tpl.py
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% import "Utils.tpl.py" as utils %}
{% macro render_userdata(namespace, userdata) %}{{ utils.render_userdata(namespace, userdata) }}{% endmacro %}
{% macro render_outcomes(outcomes, indent=0) %}{{ utils.render_outcomes(outcomes, indent) }}{% endmacro %}
{% macro render_input_keys(input_keys, indent=37) %}{{ utils.render_input_keys(input_keys, indent) }}{% endmacro %}
{% macro render_output_keys(output_keys, indent=37) %}{{ utils.render_output_keys(output_keys, indent) }}{% endmacro %}
{% macro render_goal_slots(goal_slots, indent=51) %}{{ utils.render_goal_slots(goal_slots, indent) }}{% endmacro %}
{% macro render_result_slots(result_slots, indent=51) %}{{ utils.render_result_slots(result_slots, indent) }}{% endmacro %}
{% macro render_request_slots(request_slots, indent=51) %}{{ utils.render_request_slots(request_slots, indent) }}{% endmacro %}
{% macro render_response_slots(response_slots, indent=51) %}{{ utils.render_response_slots(response_slots, indent) }}{% endmacro %}
{% macro render_def_lambda_callbacks(defined_headers, name, input_keys, callbacks) %}{{ utils.render_def_lambda_callbacks(defined_headers, '', name, '', input_keys, ['succeeded'], callbacks) }}{% endmacro %}
{% macro render_init_callbacks() %}{{ utils.render_init_callbacks() }}{% endmacro %}
{% macro render_execute_callbacks() %}{{ utils.render_execute_callbacks() }}{% endmacro %}
{% macro render_callbacks(name, callbacks, indent=51) %}{{ utils.render_callbacks(name, '', callbacks, indent) }}{% endmacro %}
{% macro render_outcome_map(outcome_map, indent=35) %}{{ utils.render_outcome_map(outcome_map, indent) }}{% endmacro %}
{% macro render_transitions(transitions, indent=23) %}{{ utils.render_transitions(transitions, indent) }}{% endmacro %}
{% macro render_remapping(remapping, indent=23) %}{{ utils.render_remapping(remapping, indent) }}{% endmacro %}
{% macro import_module(defined_headers, module) %}{{ utils.import_module(defined_headers, module) }}{% endmacro %}
{% macro import_module_as(defined_headers, module, new_name) %}{{ utils.import_module_as(defined_headers, module, new_name) }}{% endmacro %}
{% macro from_import(defined_headers, module, name) %}{{ utils.from_import(defined_headers, module, name) }}{% endmacro %}
{% macro from_import_as(defined_headers, module, name, new_name) %}{{ utils.from_import_as(defined_headers, module, name, new_name) }}{% endmacro %}
