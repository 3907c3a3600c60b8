{% block meta %}
name: ScriptImports
description: >
  Helper imported by ROSBase and the ROS state templates: the macro
  render_script_imports writes the imports that a script declares for the
  names its code uses (service, action and message types, goals, callbacks),
  from the variables import_modules and from_imports.
language: Python
framework: SMACH
type: None
tags: [core, ros]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import %}
{#- `import_modules: [M, ...]` writes `import M`; `from_imports: {M: [N, ...]}` writes
    `from M import N` (modules sorted, names in the script's order). Each line goes through
    defined_headers, so an import that the base or another state already wrote is not
    repeated. A module or name that is not a (dotted) Python identifier is never pasted as
    code: its line raises ImportError naming the text, quoted. #}
{% macro python_name_line(text, line) -%}
{% set parts = (text ~ '').split('.') -%}
{% set bad = [] -%}
{% for part in parts if not part or part | pyident != part or part[0].isdigit() -%}
{% do bad.append(part) -%}
{% endfor -%}
{% if text is string and not bad -%}
{{ line }}
{%- else -%}
raise ImportError({{ ('not a Python name: ' ~ text) | pyrepr }})
{%- endif %}
{%- endmacro %}

{% macro render_script_imports(defined_headers, import_modules, from_imports) -%}
{% set lines = [] -%}
{% for module in import_modules -%}
{% do lines.append(python_name_line(module, import_module(defined_headers, module))) -%}
{% endfor -%}
{% for module, names in from_imports | dictsort -%}
{% for name in names -%}
{% do lines.append(python_name_line(module ~ '.' ~ name, from_import(defined_headers, module, name))) -%}
{% endfor -%}
{% endfor -%}
{{ lines | reject('equalto', '') | join('\n') }}
{%- endmacro %}
