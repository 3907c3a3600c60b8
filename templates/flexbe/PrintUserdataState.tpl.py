{% block meta %}
name: PrintUserdataState
description: >
  Logs `userdata.<key>: <value>` for each of its input keys, in the order they
  are listed, then returns `succeeded`. FlexBE's LogKeyState logs one key;
  this template writes an EventState class for any number into the behavior's
  states module.
language: Python
framework: FlexBE
type: PrintUserdataState
tags: [core]
includes: []
extends: []
variables:
- - input_keys:
      description: The userdata keys to print, in this order.
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_list %}
{% set state_module = '' %}
{% set state_class = '' %}

{% set state_args = 'keys=' ~ render_list(input_keys if input_keys is defined else []) %}

{% block class_defs %}
{% if 'class_PrintUserdataState' not in defined_headers %}
class PrintUserdataState(EventState):
    """
    Logs each of the given userdata keys with its value.

    -- keys         list    The userdata keys to log.

    ># (keys)               Every key in `keys` is an input key.

    <= succeeded            The keys were logged.
    """

    def __init__(self, keys):
        super(PrintUserdataState, self).__init__(outcomes=['succeeded'], input_keys=keys)
        self._keys = keys

    def execute(self, userdata):
        for key in self._keys:
            Logger.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'
{% do defined_headers.append('class_PrintUserdataState') %}
{% endif %}
{% endblock class_defs %}
