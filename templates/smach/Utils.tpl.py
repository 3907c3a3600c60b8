{% block meta %}
name: Utils
description: >
  Macro library of the SMACH templates: userdata, outcome, key, slot, transition,
  remapping and outcome-map rendering, lambda callbacks, and imports that are
  written once per generated file (tracked in defined_headers).
language: Python
framework: SMACH
type: None
tags: [core]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{#- Every macro writes Python for the SMACH target: strings go through `pyrepr`, so that
    quotes and backslashes in names and values are escaped. Continuation lines start with
    `indent` spaces; the first line of a macro's output is never indented by the macro. -#}

{# One userdata value as Python: None stays None, a `!str` string is always quoted, a
   backtick expression is written bare, anything SMACHA's not_string accepts is written as
   code through `pycode` (numbers, lists, dicts, dotted names, calls; a string that would not
   compile as written, such as `1.2.3` or `nan`, is quoted), any other string is quoted. #}
{% macro render_value(value) -%}
{% if value is none %}None
{%- elif value is forced_string %}{{ value | pyrepr }}
{%- elif value is string and value is expression %}{{ value | exptostr }}
{%- elif value is not_string %}{{ value | pycode }}
{%- else %}{{ value | pyrepr }}
{%- endif %}
{%- endmacro %}

{# A Python list of strings: ['a', 'b']. #}
{% macro render_list(items) -%}
[{{ items | map('pyrepr') | join(', ') }}]
{%- endmacro %}

{# `<namespace>.userdata.<key> = <value>`, one line per entry, sorted by key; namespace and
   keys lower-cased. #}
{% macro render_userdata(namespace, userdata) -%}
{% for key, value in userdata.items() | sort -%}
{{ namespace | lower }}.userdata.{{ key | lower }} = {{ render_value(value) }}
{% endfor -%}
{% endmacro %}

{% macro render_outcomes(outcomes, indent=0) -%}
{{ ' ' * indent }}outcomes={{ render_list(outcomes) }}
{%- endmacro %}

{% macro render_input_keys(input_keys, indent=37) -%}
{{ ' ' * indent }}input_keys = {{ render_list(input_keys) }}
{%- endmacro %}

{% macro render_output_keys(output_keys, indent=37) -%}
{{ ' ' * indent }}output_keys = {{ render_list(output_keys) }}
{%- endmacro %}

{% macro render_goal_slots(goal_slots, indent=51) -%}
{{ ' ' * indent }}goal_slots = {{ render_list(goal_slots) }}
{%- endmacro %}

{% macro render_result_slots(result_slots, indent=51) -%}
{{ ' ' * indent }}result_slots = {{ render_list(result_slots) }}
{%- endmacro %}

{% macro render_request_slots(request_slots, indent=51) -%}
{{ ' ' * indent }}request_slots = {{ render_list(request_slots) }}
{%- endmacro %}

{% macro render_response_slots(response_slots, indent=51) -%}
{{ ' ' * indent }}response_slots = {{ render_list(response_slots) }}
{%- endmacro %}

{# The name of the function generated for a backtick (lambda) callback; without a uuid it is
   the 2017 name, `<key>_<state>_lambda_cb`. Bytes of the state name that cannot be part of an
   identifier are written `_xHH` (`pyident`). #}
{% macro lambda_callback_name(output_key, state_name, state_uuid) -%}
{{ output_key | lower }}_{{ state_name | lower | pyident }}{% if state_uuid %}_{{ state_uuid }}{% endif %}_lambda_cb
{%- endmacro %}

{# A module-level function per backtick callback of a state: it evaluates the expression on
   the userdata and stores the result in the callback's output key. The function names carry
   the state's id, so they are unique without a defined_headers marker (which would make
   every state search a list as long as the script). #}
{% macro render_def_lambda_callbacks(defined_headers, class_name, state_name, state_uuid, input_keys, outcomes, callbacks) -%}
{% for output_key, callback in callbacks.items() -%}
{% if callback is string and callback is expression -%}
@smach.cb_interface(input_keys={{ render_list(input_keys) }},
                    output_keys={{ render_list([output_key]) }},
                    outcomes={{ render_list(outcomes) }})
def {{ lambda_callback_name(output_key, state_name, state_uuid) }}(userdata):
    lambda_cb = {{ callback | exptostr }}
    userdata.{{ output_key }} = lambda_cb(userdata)
    return 'succeeded'

{% endif -%}
{% endfor -%}
{% endmacro %}

{# `callbacks = [...]` for a state's constructor: the generated function of a backtick
   callback, the name of any other. #}
{% macro render_callbacks(state_name, state_uuid, callbacks, indent=51) -%}
{{ ' ' * indent }}callbacks = [
{%- for output_key, callback in callbacks.items() -%}
{% if callback is string and callback is expression -%}
{{ lambda_callback_name(output_key, state_name, state_uuid) | pyrepr }}
{%- else -%}
{{ callback | string | pyrepr }}
{%- endif %}{% if not loop.last %}, {% endif %}
{%- endfor %}]
{%- endmacro %}

{# Python for a state class's __init__ (8 spaces deep): look the named callbacks up among
   the module's functions and register their keys and outcomes with the state. They run in
   the order of the constructor's `callbacks` list, the script's order (SMACHA sorts them by
   function name; smachac keeps the script's order, as its C++ target does). #}
{% macro render_init_callbacks() %}
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])
{% endmacro %}

{# Python for a state class's execute() (8 spaces deep): run every callback on a view of the
   userdata limited to its keys. #}
{% macro render_execute_callbacks() %}
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))
{% endmacro %}

{# `outcome_map={'outcome': { 'CHILD': 'child_outcome', ...}, ...}`, both levels sorted;
   continuation lines start with indent+13 spaces. #}
{% macro render_outcome_map(outcome_map, indent=35) -%}
{{ ' ' * indent }}outcome_map={{ '{' }}
{%- for outcome, condition in outcome_map.items() | sort -%}
{{ outcome | pyrepr }}: {% if condition is mapping -%}
{{ '{' }} {% for child, child_outcome in condition.items() | sort -%}
{{ child | pyrepr }}: {{ child_outcome | pyrepr }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- else %}{{ condition | pyrepr }}{% endif %}
{%- if not loop.last %},
{{ ' ' * (indent + 13) }}{% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# `transitions={'outcome':'TARGET', ...}`, sorted; continuation lines at indent+13. #}
{% macro render_transitions(transitions, indent=23) -%}
{{ ' ' * indent }}transitions={{ '{' }}
{%- for outcome, target in transitions.items() | sort -%}
{{ outcome | pyrepr }}:{{ target | pyrepr }}{% if not loop.last %},
{{ ' ' * (indent + 13) }}{% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# `remapping={'state_key':'parent_key', ...}`, sorted; continuation lines at indent+11. #}
{% macro render_remapping(remapping, indent=23) -%}
{{ ' ' * indent }}remapping={{ '{' }}
{%- for key, parent_key in remapping.items() | sort -%}
{{ key | pyrepr }}:{{ parent_key | pyrepr }}{% if not loop.last %},
{{ ' ' * (indent + 11) }}{% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# The arguments of a state class constructor that State.tpl.py writes:
   input_keys, output_keys, callbacks, outcomes, each when the state gives it. #}
{% macro render_state_arguments(state_name, state_uuid, input_keys, output_keys, callbacks, outcomes) -%}
{% set arguments = [] -%}
{% if input_keys is defined %}{% do arguments.append(render_input_keys(input_keys, indent=0)) %}{% endif -%}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif -%}
{% if callbacks is defined %}{% do arguments.append(render_callbacks(state_name, state_uuid, callbacks, indent=0)) %}{% endif -%}
{% if outcomes is defined %}{% do arguments.append(render_outcomes(outcomes, indent=0)) %}{% endif -%}
{{ arguments | join(', ') }}
{%- endmacro %}

{# A container's body after its constructor: the header code its children filed under its
   name, its own userdata and then its children's, the children added inside `with`, and the
   container added to its parent (without transitions in a Concurrence). #}
{% macro render_container_contents(name, sm_name, parent_type, header, userdata, header_userdata, body, transitions, remapping) -%}
{% if name in header %}
{{ header[name] }}
{%- endif %}
{%- if userdata is defined %}
{{ render_userdata(sm_name, userdata) }}
{%- endif %}
{%- if name in header_userdata %}
{{ header_userdata[name] }}
{%- endif %}

with {{ sm_name }}:
    {{ body | indent(4) }}

smach.{{ parent_type }}.add({{ name | pyrepr }}, {{ sm_name }}
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{%- endmacro %}

{# Imports, each written once per generated file. #}
{% macro import_module(defined_headers, module) -%}
{% if 'import_' + module not in defined_headers -%}
import {{ module }}{% do defined_headers.append('import_' + module) %}
{%- endif %}
{%- endmacro %}

{% macro import_module_as(defined_headers, module, new_name) -%}
{% set marker = 'import_' + module + '_as_' + new_name -%}
{% if marker not in defined_headers -%}
import {{ module }} as {{ new_name }}{% do defined_headers.append(marker) %}
{%- endif %}
{%- endmacro %}

{% macro from_import(defined_headers, module, name) -%}
{% set marker = 'from_' + module + '_import_' + name -%}
{% if marker not in defined_headers -%}
from {{ module }} import {{ name }}{% do defined_headers.append(marker) %}
{%- endif %}
{%- endmacro %}

{% macro from_import_as(defined_headers, module, name, new_name) -%}
{% set marker = 'from_' + module + '_import_' + name + '_as_' + new_name -%}
{% if marker not in defined_headers -%}
from {{ module }} import {{ name }} as {{ new_name }}{% do defined_headers.append(marker) %}
{%- endif %}
{%- endmacro %}
