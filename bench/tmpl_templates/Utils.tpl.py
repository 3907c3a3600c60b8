{% block meta %}
name: Utils
description: Macros of the benchmark templates (shaped like SMACHA's Utils.tpl.py).
{% endblock meta %}

{% macro render_userdata(namespace, userdata) %}
{% for key, value in userdata.items() | sort %}
{{ namespace | lower() }}.userdata.{{ key | lower() }} = {% if value is not_string %}{{ value }}{% else %}'{{ value }}'{% endif %}

{% endfor %}
{% endmacro %}

{% macro render_outcomes(outcomes, indent=0) %}{{ 'outcomes=' | indent(indent, true) }}[{% for outcome in outcomes %}'{{ outcome }}'{% if not loop.last %}, {% endif %}{% endfor %}]{% endmacro %}

{% macro render_input_keys(input_keys, indent=37) %}{{ 'input_keys=' | indent(indent, true) }}[{% for key in input_keys %}'{{ key }}'{% if not loop.last %}, {% endif %}{% endfor %}]{% endmacro %}

{% macro render_output_keys(output_keys, indent=37) %}{{ 'output_keys=' | indent(indent, true) }}[{% for key in output_keys %}'{{ key }}'{% if not loop.last %}, {% endif %}{% endfor %}]{% endmacro %}

{% macro render_transitions(transitions, indent=23) %}{{ 'transitions=' | indent(indent, true) }}{{ '{' }}{% for outcome, target in transitions.items() | sort %}'{{ outcome }}':'{{ target }}'{% if not loop.last %},
{{ '' | indent(indent + 13, true) }}{% endif %}{% endfor %}{{ '}' }}{% endmacro %}

{% macro render_remapping(remapping, indent=23) %}{{ 'remapping=' | indent(indent, true) }}{{ '{' }}{% for key, value in remapping.items() | sort %}'{{ key }}':'{{ value }}'{% if not loop.last %},
{{ '' | indent(indent + 11, true) }}{% endif %}{% endfor %}{{ '}' }}{% endmacro %}

{% macro import_module(defined_headers, module) %}
{% if 'import_' + module not in defined_headers %}
import {{ module }}
{% do defined_headers.append('import_' + module) %}
{% endif %}{% endmacro %}
