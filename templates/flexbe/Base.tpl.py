{% block meta %}
name: Base
description: >
  The base template of a FlexBE behavior, shaped as FlexBE's generator
  writes it: the behavior module
  `<name>_sm.py` (header, imports, the Behavior class with __init__ and
  create(), the four [MANUAL] sections), then, each after a
  `#@smachac-file <path>` line that the target splits on, the module of the
  generated EventState classes (when there are any) and the manifest: XML
  (XML, and for ROS 2 also the Python dict `<name>_manifest.py`; -flexbe-ros).
  The FlexBE target sets the globals `behavior_parameters` ([{name, value}]),
  `contained_behaviors` ([{name, id}]: the embedded behaviors) and
  `main_behavior` (the script's name, which names the package).
language: Python
framework: FlexBE
type: Base
tags: [core]
includes: []
extends: []
variables:
- outcomes:
    description: The outcomes of the behavior.
    type: list of str
- - userdata:
      description: Userdata defaults of the behavior's state machine, by key.
      type: dict
- - input_keys:
      description: The behavior's input keys.
      type: list of str
- - output_keys:
      description: The behavior's output keys.
      type: list of str
- - manifest:
      description: The ROS package of the behavior (default <name>_flexbe_behaviors).
      type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import container_args, render_userdata, render_value, outcome_layout, class_prefix, behavior_file, parameter_type, parameter_default %}
{#- Exported to every state: the package and file stem of the generated modules. #}
{%- set defined_headers = [] %}
{%- set local_vars = ['behavior_class', 'core_imports', 'parameters', 'contained'] %}
{%- set flexbe_file = behavior_file(name) %}
{%- set flexbe_package = behavior_file(main_behavior | default(name)) ~ '_flexbe_behaviors' %}
{%- set parameters = behavior_parameters | default([]) %}
{%- set contained = contained_behaviors | default([]) %}
{%- set behavior_class = class_prefix(name) ~ 'SM' %}
{%- set core_imports = ['Autonomy', 'Behavior', 'ConcurrencyContainer', 'Logger', 'OperatableStateMachine', 'PriorityContainer'] %}
{%- block base_header %}
#@smachac-file {{ flexbe_file }}_sm.py
#!/usr/bin/env python
# -*- coding: utf-8 -*-
{%- if flexbe_ros == 2 %}

# Copyright 2026 smachac
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
{%- endif %}

###########################################################
#               WARNING: Generated code!                  #
#              **************************                 #
# Manual changes may get lost if file is generated again. #
# Only code inside the [MANUAL] tags will be kept.        #
###########################################################
{%- if flexbe_ros == 2 %}

"""
Define {{ name }}.

Created by smachac from a SMACHA script.
"""
{%- endif %}
{%- endblock base_header %}
{%- block imports %}

{% if flexbe_ros == 2 %}
{%- for symbol in core_imports + ['initialize_flexbe_core'] %}
from flexbe_core import {{ symbol }}
{%- endfor %}
{%- else %}
from flexbe_core import {{ core_imports[1] }}, {{ core_imports[0] }}, {{ core_imports[4] }}, {{ core_imports[2] }}, {{ core_imports[5] }}, {{ core_imports[3] }}
{%- endif %}
{%- if imports %}
{{ imports | replace('\n\n', '\n') }}
{%- endif %}
# Additional imports can be added inside the following tags
# [MANUAL_IMPORT]

# [/MANUAL_IMPORT]
{%- endblock imports %}
{%- block main_def %}
{%- if flexbe_ros != 2 %}


'''
Created by smachac from a SMACHA script.
'''
{%- endif %}


class {{ behavior_class }}(Behavior):
    {{ '"""' if flexbe_ros == 2 else "'''" }}
    Define {{ name }}.
    {{ '"""' if flexbe_ros == 2 else "'''" }}

    def __init__(self{{ ', node' if flexbe_ros == 2 }}):
        super({{ behavior_class }}, self).__init__()
        self.name = {{ name | pyrepr }}
{%- if flexbe_ros == 2 %}
        self.node = node
        initialize_flexbe_core(node)
{%- endif %}

        # parameters of this behavior
{%- for parameter in parameters %}
        self.add_parameter({{ parameter.name | pyrepr }}, {{ render_value(parameter.value) }})
{%- endfor %}

        # references to used behaviors
{%- for behavior in contained %}
        self.add_behavior({{ class_prefix(behavior.name) }}SM, {{ behavior.id | pyrepr }}{{ ', node' if flexbe_ros == 2 }})
{%- endfor %}

        # Additional initialization code can be added inside the following tags
        # [MANUAL_INIT]

        # [/MANUAL_INIT]

        # Behavior comments:

    def create(self):
{%- if flexbe_ros == 2 %}
        """Create state machine."""
{%- endif %}
        {{ outcome_layout(outcomes) }}
        _state_machine = OperatableStateMachine({{ container_args(outcomes, input_keys, output_keys) }})
{%- if userdata is defined %}
        {{ render_userdata('_state_machine', userdata) | trim | indent(8) }}
{%- endif %}
{%- if name in header and header[name] %}
        {{ header[name] | trim | indent(8) }}
{%- endif %}

        # Additional creation code can be added inside the following tags
        # [MANUAL_CREATE]

        # [/MANUAL_CREATE]
{%- if main_def %}

        {{ main_def | indent(8) }}
{%- endif %}
{%- endblock main_def %}
{%- block body %}

        with _state_machine:
            {{ body | indent(12) }}

        return _state_machine

    # Private functions can be added inside the following tags
    # [MANUAL_FUNC]

    # [/MANUAL_FUNC]
{%- endblock body %}
{%- block class_defs %}
{%- if class_defs %}
#@smachac-file {{ flexbe_file }}_states.py
#!/usr/bin/env python
# -*- coding: utf-8 -*-
"""EventState classes generated by smachac for the {{ name }} behavior."""

from flexbe_core import EventState, Logger


{{ class_defs }}
{%- endif %}
{%- endblock class_defs %}
{%- block base_footer %}
#@smachac-file {{ flexbe_file }}.xml
<?xml version="1.0" encoding="UTF-8"?>

<behavior name="{{ name | e }}">

	<executable package_path="{{ flexbe_package }}.{{ flexbe_file }}_sm" class="{{ behavior_class }}" />
	<tagstring></tagstring>
	<author>smachac</author>
	<date></date>
	<description>
		Generated by smachac from {{ name | e }}
	</description>


	<!-- Contained Behaviors -->
{%- for behavior_name in contained | map(attribute='name') | unique %}
	<contains name="{{ behavior_name | e }}" />
{%- endfor %}

	<!-- Available Parameters -->
{%- if parameters %}
	<params>
{%- for parameter in parameters %}

		<param type="{{ parameter_type(parameter.value) }}" name="{{ parameter.name }}" default="{{ parameter_default(parameter.value) | e }}" label="{{ parameter.name }}" hint="Sets the {{ parameter.name }}" />
{%- endfor %}

	</params>
{%- endif %}


</behavior>
{%- if flexbe_ros == 2 %}
#@smachac-file {{ flexbe_file }}_manifest.py
"""Manifest of the {{ name }} behavior."""

{{ flexbe_file }} = {
    'executable': {
        'package_path': {{ (flexbe_package ~ '.' ~ flexbe_file ~ '_sm') | pyrepr }},
        'class': {{ behavior_class | pyrepr }},
    },
    'name': {{ name | pyrepr }},
    'description': {{ ('Generated by smachac from ' ~ name) | pyrepr }},
    'tagstring': '',
    'author': 'smachac',
    'date': '',
    'contains': [{{ contained | map(attribute='name') | unique | map('pyrepr') | join(', ') }}],
    'params': [
{%- for parameter in parameters %}
        {'type': {{ parameter_type(parameter.value) | pyrepr }}, 'name': {{ parameter.name | pyrepr }}, 'default': {{ render_value(parameter.value) }}, 'label': {{ parameter.name | pyrepr }}, 'hint': {{ ('Sets the ' ~ parameter.name) | pyrepr }}},
{%- endfor %}
{%- if parameters %}
    {% endif %}],
}
{%- endif %}
{%- endblock base_footer %}
