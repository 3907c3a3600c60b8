{% block meta %}
name: CallbacksState
description: >
  Runs its callbacks on the userdata, in the script's order, each writing the
  output key it is listed under, then returns `succeeded`. FlexBE has no
  library equivalent: the template writes an EventState class into the
  behavior's states module, and each callback becomes an entry of its
  `callbacks` argument.
language: Python
framework: FlexBE
type: CallbacksState
tags: [core]
includes: []
extends: []
variables:
- callbacks:
    description: >
      Callbacks by output key, run in the script's order, each computing the
      value of its key from the userdata:
      a backtick-wrapped Python lambda of the userdata or a portable `!expr`
      expression (a function name is not a callback here).
    type: dict of str
- - input_keys:
      description: The userdata keys the callbacks read.
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_list, render_callbacks %}
{% set state_module = '' %}
{% set state_class = '' %}

{# Each callback's key is an output key, declared or not (as for the other targets). #}
{% set written = (output_keys if output_keys is defined else []) | list %}
{% for key in callbacks if key not in written %}{% do written.append(key) %}{% endfor %}
{% set state_args = 'callbacks=' ~ render_callbacks(callbacks)
    ~ ', input_keys=' ~ render_list(input_keys if input_keys is defined else [])
    ~ ', output_keys=' ~ render_list(written) %}

{% block class_defs %}
{% if 'class_CallbacksState' not in defined_headers %}
class CallbacksState(EventState):
    """
    Runs its callbacks on the userdata, in order; each computes the value of the
    output key it is listed under.

    -- callbacks    dict    Output key -> function of the userdata.
    -- input_keys   list    The userdata keys the callbacks read.
    -- output_keys  list    The userdata keys the callbacks write.

    <= succeeded            The callbacks have run.
    """

    def __init__(self, callbacks, input_keys, output_keys):
        super(CallbacksState, self).__init__(outcomes=['succeeded'], input_keys=input_keys,
                                             output_keys=output_keys)
        self._callbacks = callbacks

    def execute(self, userdata):
        for key, callback in self._callbacks.items():
            userdata[key] = callback(userdata)
        return 'succeeded'
{% do defined_headers.append('class_CallbacksState') %}
{% endif %}
{% endblock class_defs %}
