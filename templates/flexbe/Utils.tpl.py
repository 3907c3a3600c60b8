{% block meta %}
name: Utils
description: >
  Macro library of the FlexBE templates: values, lists, transitions, autonomy
  levels, remappings, conditions, container variables, layout comments and
  state-class imports written once per behavior (tracked in defined_headers).
language: Python
framework: FlexBE
type: None
tags: [core]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{#- Every macro writes Python in the shape the FlexBE editor parses back:
    each call is one line, strings go through `pyrepr`. -#}

{# One value as Python: None stays None, a `!str` string is quoted, a backtick expression is
   bare, non-strings as Python literals (`pyliteral`: nan is float('nan')), other strings quoted. #}
{% macro render_value(value) -%}
{% if value is none %}None
{%- elif value is forced_string %}{{ value | pyrepr }}
{%- elif value is string and value is expression %}{{ value | exptostr }}
{%- elif value is string %}{{ value | pyrepr }}
{%- else %}{{ value | pyliteral }}
{%- endif %}
{%- endmacro %}

{% macro render_list(items) -%}
[{{ items | map('pyrepr') | join(', ') }}]
{%- endmacro %}

{# The keyword arguments of a generated file state: its input keys (the ones it always reads
   first), output keys (the script's and the callbacks'), and callbacks. #}
{% macro file_state_args(own_keys, input_keys, output_keys, callbacks) -%}
{%- set reads = own_keys | list -%}
{%- for key in (input_keys if input_keys is defined else []) if key not in reads %}{% do reads.append(key) %}{% endfor -%}
{%- set written = (output_keys if output_keys is defined else []) | list -%}
{%- for key in (callbacks if callbacks is defined else {}) if key not in written %}{% do written.append(key) %}{% endfor -%}
input_keys={{ render_list(reads) }}, output_keys={{ render_list(written) }}, callbacks={{ render_callbacks(callbacks if callbacks is defined else {}) }}
{%- endmacro %}

{# A state's callbacks as a dict literal, output key -> the value (a backtick lambda is bare);
   Python keeps the script's order. #}
{% macro render_callbacks(callbacks) -%}
{{ '{' }}{% for key, callback in callbacks.items() %}{{ key | pyrepr }}: {{ render_value(callback) }}{% if not loop.last %}, {% endif %}{% endfor %}{{ '}' }}
{%- endmacro %}

{# The keyword arguments of a container constructor. #}
{% macro container_args(outcomes, input_keys, output_keys) -%}
outcomes={{ render_list(outcomes) }}
{%- if input_keys is defined and input_keys %}, input_keys={{ render_list(input_keys) }}{% endif %}
{%- if output_keys is defined and output_keys %}, output_keys={{ render_list(output_keys) }}{% endif %}
{%- endmacro %}

{# The variable of the container whose children are being rendered: the root (a base
   template: Base, BaxterBase, ...) is `_state_machine`, a sub-container `_sm_<name>`. #}
{% macro parent_var(parent_template, parent_sm_name) -%}
{% if parent_template.endswith('Base') %}_state_machine{% else %}_{{ parent_sm_name }}{% endif %}
{%- endmacro %}

{% macro render_userdata(var, userdata) -%}
{% for key, value in userdata.items() | sort -%}
{{ var }}.userdata.{{ key }} = {{ render_value(value) }}
{% endfor -%}
{%- endmacro %}

{# A layout comment `# x:N y:M`; positions step down the editor's canvas in state order. #}
{% macro layout(defined_headers) -%}
{% do defined_headers.append('flexbe_layout') -%}
{% set n = defined_headers | select('equalto', 'flexbe_layout') | list | length -%}
# x:{{ 30 + 200 * ((n - 1) % 4) }} y:{{ 40 + 120 * ((n - 1) // 4) }}
{%- endmacro %}

{# An autonomy level: Off/Low/High/Full/Inherit (any case) or 0-3; an unknown level fails the
   render, and the error names the level and the state. #}
{% macro autonomy_level(level) -%}
{% set names = {'off': 'Off', 'low': 'Low', 'high': 'High', 'full': 'Full', 'inherit': 'Inherit',
                '0': 'Off', '1': 'Low', '2': 'High', '3': 'Full'} -%}
{% set key = level | string | lower -%}
Autonomy.{{ names[key] if key in names else names[key].unknown_autonomy_level }}
{%- endmacro %}

{% macro render_transitions(transitions) -%}
transitions={{ '{' }}
{%- for outcome, target in transitions.items() | sort -%}
{{ outcome | pyrepr }}: {{ target | pyrepr }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# Autonomy per outcome: a mapping outcome -> level, or one level for every outcome. #}
{% macro render_autonomy(transitions, autonomy) -%}
autonomy={{ '{' }}
{%- for outcome, target in transitions.items() | sort -%}
{% if autonomy is not defined %}{% set level = 'Off' %}
{%- elif autonomy is mapping %}{% set level = autonomy.get(outcome, 'Off') %}
{%- else %}{% set level = autonomy %}{% endif -%}
{{ outcome | pyrepr }}: {{ autonomy_level(level) }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# remapping: input keys first, then output keys that are not inputs, as FlexBE's generator writes it. #}
{% macro render_remapping(input_keys, output_keys, remapping) -%}
{% set keys = (input_keys or []) + ((output_keys or []) | reject('in', input_keys or []) | list) -%}
{% set ns = namespace(items=[]) -%}
{% for key in keys %}{% do ns.items.append(key | pyrepr ~ ': ' ~ (remapping.get(key, key) if remapping is defined else key) | pyrepr) %}{% endfor -%}
{% if remapping is defined %}{% for key, target in remapping.items() | sort %}{% if key not in keys %}{% do ns.items.append(key | pyrepr ~ ': ' ~ target | pyrepr) %}{% endif %}{% endfor %}{% endif -%}
remapping={{ '{' }}{{ ns.items | join(', ') }}{{ '}' }}
{%- endmacro %}

{# The remapping as the last argument of `OperatableStateMachine.add`: `, remapping={...}`,
   or nothing when it would be empty, as FlexBE's own code generator writes it (its editor
   cannot parse `remapping={}`). #}
{% macro remapping_argument(input_keys, output_keys, remapping) -%}
{% set text = render_remapping(input_keys, output_keys, remapping) -%}
{% if text != 'remapping={}' %}, {{ text }}{% endif -%}
{%- endmacro %}

{# ConcurrencyContainer conditions from a SMACH outcome_map: one conjunction per outcome, then
   one per combination of the children's outcomes for the default outcome. FlexBE takes the
   first that holds, so the entries come in SMACH 2.5's order (stdlib/runtime/README.md,
   "Choosing among outcome_map entries"): more conditions first, then sorted by outcome;
   entries without conditions, which SMACH 2.5 never chooses, are left out. #}
{% macro render_conditions(outcome_map, default_outcome='', default_conditions=[]) -%}
{% set ranked = namespace(items=[]) -%}
{% for outcome, condition in outcome_map.items() | sort -%}
{% if condition | length > 0 %}{% do ranked.items.append((condition | length, outcome, condition.items() | sort)) %}{% endif %}
{%- endfor -%}
{% set ns = namespace(items=[]) -%}
{% for size, outcome, pairs in ranked.items | sort(attribute='0', reverse=true) -%}
{% do ns.items.append((outcome, pairs)) %}
{%- endfor -%}
{% for condition in default_conditions %}{% do ns.items.append((default_outcome, condition)) %}{% endfor -%}
conditions=[
{%- for outcome, pairs in ns.items -%}
({{ outcome | pyrepr }}, [
{%- for child, child_outcome in pairs -%}
({{ child | pyrepr }}, {{ child_outcome | pyrepr }}){% if not loop.last %}, {% endif %}
{%- endfor %}]){% if not loop.last %}, {% endif %}
{%- endfor %}]
{%- endmacro %}

{# The name a state class is used under: the class itself, or `<pkg>__<Class>` when another
   module imported a class of the same name first. #}
{% macro class_ref(defined_headers, module, cls) -%}
{% set ns = namespace(owner=module) -%}
{% for h in defined_headers | reverse %}{% if h.startswith('flexbe_class:' ~ cls ~ '=') %}{% set ns.owner = h.split('=', 1)[1] %}{% endif %}{% endfor -%}
{% if ns.owner == module %}{{ cls }}{% else %}{{ module.split('.')[0] }}__{{ cls }}{% endif %}
{%- endmacro %}

{# One import per state class, aliased on a clash with an earlier import. #}
{% macro import_state(defined_headers, module, cls) -%}
{% set marker = 'flexbe_import:' ~ module ~ '.' ~ cls -%}
{% if marker not in defined_headers -%}
{% set ref = class_ref(defined_headers, module, cls) -%}
{% if ref == cls %}{% do defined_headers.append('flexbe_class:' ~ cls ~ '=' ~ module) %}from {{ module }} import {{ cls }}
{%- else %}from {{ module }} import {{ cls }} as {{ ref }}{% endif -%}
{% do defined_headers.append(marker) %}
{%- endif %}
{%- endmacro %}

{# The layout comment of a container's outcomes: `# x:30 y:365, x:130 y:365`. #}
{% macro outcome_layout(outcomes) -%}
# {% for outcome in outcomes %}x:{{ 30 + 100 * loop.index0 }} y:365{% if not loop.last %}, {% endif %}{% endfor %}
{%- endmacro %}

{# A behavior name as a file stem: lower case, spaces and dashes as `_`. #}
{% macro behavior_file(name) -%}
{{ (name | lower).replace(' ', '_').replace('-', '_') }}
{%- endmacro %}

{# A behavior parameter's type in the manifest (FlexBE's text, numeric and boolean types), and
   its default as the manifest writes it. #}
{% macro parameter_type(value) -%}
{% if value is boolean %}boolean{% elif value is number %}numeric{% else %}text{% endif %}
{%- endmacro %}

{% macro parameter_default(value) -%}
{% if value is boolean or value is number %}{{ value | pyliteral }}{% else %}{{ value }}{% endif %}
{%- endmacro %}

{# A behavior name as a Python class name: words capitalised, non-word characters dropped. #}
{% macro class_prefix(name) -%}
{% for word in (name | replace('-', ' ') | replace('_', ' ')).split() %}{{ word[0] | upper }}{{ word[1:] }}{% endfor %}
{%- endmacro %}
