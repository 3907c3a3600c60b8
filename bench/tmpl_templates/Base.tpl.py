{% block meta %}
name: Base
description: The module layout (benchmark, shaped like SMACHA's Base.tpl.py).
{% endblock meta %}
{% set defined_headers = [] %}
{% if name is defined %}{% set sm_name = name | lower() %}{% else %}{% set sm_name = 'sm' %}{% endif %}
#!/usr/bin/env python
{{ base_header }}
import smach
{{ imports }}
{{ defs }}
{{ class_defs }}
{{ cb_defs }}

def main():
{{ main_def | indent(4, true) }}
    {{ sm_name }} = smach.StateMachine(outcomes=[{% for o in outcomes %}'{{ o }}'{% if not loop.last %}, {% endif %}{% endfor %}])
{% if sm_name in header %}
    {{ header[sm_name] | indent(4) }}
{% endif %}

    with {{ sm_name }}:
        {{ body | indent(8) }}

{{ footer | indent(4, true) }}
{{ execute | indent(4, true) }}
    outcome = {{ sm_name }}.execute()
{{ base_footer | indent(4, true) }}

if __name__ == '__main__':
    main()
