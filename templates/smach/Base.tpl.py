{% block meta %}
name: Base
description: >
  The base template of a plain SMACH script (no ROS): imports, definitions,
  the main function that builds the top state machine from the states' code,
  runs it, and the `__main__` guard.
language: Python
framework: SMACH
type: Base
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes of the top state machine.
    type: list of str
- - userdata:
      description: Userdata of the top state machine, by key.
      type: dict
- - function_name:
      description: The name of the generated main function (default main).
      type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_outcomes, render_userdata %}
{#- The base's own imports go through defined_headers: running this template once before the
    states pre-seeds the list, so that no state imports them again. #}
{%- set defined_headers = [] %}
{#- Names in local_vars stay local to this template: they are not exported to the states. #}
{%- set local_vars = ['main_function'] %}
{%- set sm_name = name | lower if name is defined else 'sm' %}
{%- set main_function = function_name | lower if function_name is defined else 'main' %}
{%- block base_header %}
#!/usr/bin/env python
{%- if base_header %}
{{ base_header }}
{%- endif %}
{%- endblock base_header %}
{%- block imports %}

{{ import_module(defined_headers, 'smach') }}
{%- if imports %}
{{ imports }}
{%- endif %}
{%- endblock imports %}
{%- block defs %}
{%- if defs %}


{{ defs }}
{%- endif %}
{%- endblock defs %}
{%- block class_defs %}
{%- if class_defs %}


{{ class_defs }}
{%- endif %}
{%- endblock class_defs %}
{%- block cb_defs %}
{%- if cb_defs %}


{{ cb_defs }}
{%- endif %}
{%- endblock cb_defs %}
{%- block main_def %}


def {{ main_function }}():
{%- if main_def %}
    {{ main_def | indent(4) }}
{%- endif %}
{%- endblock main_def %}
{%- block body %}
    {{ sm_name }} = smach.StateMachine({{ render_outcomes(outcomes) }})
{%- if name in header %}
    {{ header[name] | indent(4) }}
{%- endif %}
{%- if userdata is defined %}
    {{ render_userdata(sm_name, userdata) | indent(4) }}
{%- endif %}
{%- if name in header_userdata %}
    {{ header_userdata[name] | indent(4) }}
{%- endif %}

    with {{ sm_name }}:
        {{ body | indent(8) }}
{%- endblock body %}
{%- block footer %}
{%- if footer %}
        {{ footer | indent(8) }}
{%- endif %}
{%- endblock footer %}
{#- A plain SMACH script has no introspection server; ROSBase fills these two blocks (-i). #}
{%- block introspection_server %}
{%- endblock introspection_server %}
{%- block execute %}
{%- if execute %}

    {{ execute | indent(4) }}
{%- endif %}

    outcome = {{ sm_name }}.execute()
{%- endblock execute %}
{%- block spin %}
{%- endblock spin %}
{%- block base_footer %}
{%- if base_footer %}

    {{ base_footer | indent(4) }}
{%- endif %}
{%- endblock base_footer %}
{%- block main %}


if __name__ == '__main__':
    {{ main_function }}()
{%- endblock main %}
